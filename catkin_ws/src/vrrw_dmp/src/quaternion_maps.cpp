#include <vrrw_dmp/quaternion_maps.h>

#include <cmath>

namespace vrrw_dmp
{
Eigen::Vector3d quaternionLog(const Eigen::Quaterniond& q)
{
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const Eigen::Vector3d v = sign * q.vec();
  const double sine = v.norm();
  if (sine < 1e-12)
    return v;  // sin(x) / x = 1 to double precision here
  return std::atan2(sine, sign * q.w()) / sine * v;
}

Eigen::Quaterniond quaternionExp(const Eigen::Vector3d& v)
{
  const double half_angle = v.norm();
  if (half_angle < 1e-12)
    return Eigen::Quaterniond(1.0, v.x(), v.y(), v.z()).normalized();
  const Eigen::Vector3d axis = std::sin(half_angle) / half_angle * v;
  return Eigen::Quaterniond(std::cos(half_angle), axis.x(), axis.y(), axis.z());
}

Eigen::Vector3d rotationBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
  return 2.0 * quaternionLog(a * b.conjugate());
}

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
  return rotationBetween(a, b).norm();
}
}  // namespace vrrw_dmp
