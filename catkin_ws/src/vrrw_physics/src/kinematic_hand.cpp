#include "kinematic_hand.h"

#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <LinearMath/btDefaultMotionState.h>

#include <algorithm>

#include "bullet_conversions.h"

namespace vrrw_physics
{
KinematicHand::KinematicHand(btDiscreteDynamicsWorld& world, double radius, const Eigen::Isometry3d& pose, double now)
  : world_(world), radius_(radius), from_(pose), to_(pose), start_(now), last_update_(now)
{
  shape_ = std::make_unique<btSphereShape>(btScalar(radius));
  motion_ = std::make_unique<btDefaultMotionState>(toBullet(pose));
  btRigidBody::btRigidBodyConstructionInfo info(0, motion_.get(), shape_.get());
  info.m_friction = btScalar(1.0);
  body_ = std::make_unique<btRigidBody>(info);
  // Kinematic: Bullet takes its velocity from the motion state's change over each step.
  body_->setCollisionFlags(body_->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  body_->setActivationState(DISABLE_DEACTIVATION);
  world_.addRigidBody(body_.get());
}

KinematicHand::~KinematicHand()
{
  world_.removeRigidBody(body_.get());
}

const btCollisionObject* KinematicHand::body() const
{
  return body_.get();
}

void KinematicHand::track(const Eigen::Isometry3d& pose, double now)
{
  Eigen::Isometry3d current;
  toEigen(body_->getWorldTransform(), current);
  from_ = current;
  to_ = pose;
  duration_ = std::min(now - last_update_, kMaxGlide);
  start_ = now;
  last_update_ = now;
}

void KinematicHand::advance(double now, double dt)
{
  const double s = duration_ > 0.0 ? std::clamp((now + dt - start_) / duration_, 0.0, 1.0) : 1.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = (1.0 - s) * from_.translation() + s * to_.translation();
  pose.linear() = Eigen::Quaterniond(from_.rotation()).slerp(s, Eigen::Quaterniond(to_.rotation())).toRotationMatrix();
  motion_->setWorldTransform(toBullet(pose));
}
}  // namespace vrrw_physics
