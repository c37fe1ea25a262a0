#pragma once
// Eigen <-> Bullet. Bullet as packaged is single precision: every conversion to it rounds to float,
// every conversion back is exact.
#include <LinearMath/btTransform.h>

#include <Eigen/Geometry>

namespace vrrw_physics
{
inline btVector3 toBullet(const Eigen::Vector3d& v)
{
  return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}

inline btQuaternion toBullet(const Eigen::Quaterniond& q)
{
  return btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w()));
}

inline btTransform toBullet(const Eigen::Isometry3d& t)
{
  return btTransform(toBullet(Eigen::Quaterniond(t.rotation())), toBullet(Eigen::Vector3d(t.translation())));
}

inline Eigen::Vector3d toEigen(const btVector3& v)
{
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

/// \brief Writes a Bullet transform into `pose` (every entry, no allocation: used on every link each step).
inline void toEigen(const btTransform& t, Eigen::Isometry3d& pose)
{
  pose.setIdentity();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      pose.matrix()(r, c) = t.getBasis()[r][c];
    pose.matrix()(r, 3) = t.getOrigin()[r];
  }
}

inline Eigen::Isometry3d toEigen(const btTransform& t)
{
  Eigen::Isometry3d pose;
  toEigen(t, pose);
  return pose;
}
}  // namespace vrrw_physics
