#include <vrrw_physics/input_limits.h>
#include <vrrw_physics/rigid_object.h>

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bullet_conversions.h"
#include "collision_shape.h"

namespace vrrw_physics
{
RigidObject::RigidObject(const vrrw_scene::Object& object)
  : name_(object.name), fixed_(object.fixed || object.mass <= 0.0)
{
  if (object.collision.empty())
    throw std::runtime_error("object " + name_ + ": no collision shapes");
  if (!fixed_ && (!object.inertia.allFinite() || !object.center_of_mass.allFinite() || !std::isfinite(object.mass)))
    throw std::runtime_error("object " + name_ + ": mass, centre of mass or inertia is not finite");
  try
  {
    requireWorkspacePose(object.pose, "object " + name_);
  }
  catch (const InputError& e)
  {
    throw std::runtime_error(e.what());
  }
  object_T_body_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d principal = Eigen::Vector3d::Zero();
  const bool given_inertia = object.inertia.trace() > 0.0;
  if (!fixed_)
  {
    object_T_body_.translate(object.center_of_mass);
    if (given_inertia)
    {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (object.inertia + object.inertia.transpose()));
      Eigen::Matrix3d axes = eig.eigenvectors();
      if (axes.determinant() < 0)
        axes.col(2) = -axes.col(2);
      object_T_body_.rotate(axes);
      principal = eig.eigenvalues().cwiseMax(1e-9);
    }
  }
  auto compound = std::make_unique<btCompoundShape>(true, int(object.collision.size()));
  const Eigen::Isometry3d body_T_object = object_T_body_.inverse();
  for (const vrrw_scene::Shape& shape : object.collision)
  {
    try
    {
      shapes_.push_back(makeCollisionShape(shape));
    }
    catch (const std::runtime_error& e)
    {
      throw std::runtime_error("object " + name_ + ": collision " + e.what());
    }
    compound->addChildShape(toBullet(body_T_object * shape.origin), shapes_.back().get());
  }
  btVector3 inertia = toBullet(principal);
  const btScalar mass = fixed_ ? btScalar(0) : btScalar(object.mass);
  if (!fixed_ && !given_inertia)
    compound->calculateLocalInertia(mass, inertia);
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, compound.get(), inertia);
  info.m_friction = btScalar(object.friction);
  info.m_restitution = btScalar(object.restitution);
  info.m_startWorldTransform = toBullet(object.pose * object_T_body_);
  shapes_.push_back(std::move(compound));
  body_ = std::make_unique<btRigidBody>(info);
  body_->setRollingFriction(btScalar(0.0));
  if (!fixed_)
  {
    // Continuous collision: a body flung at speed must not tunnel through a thin table top.
    btVector3 low, high;
    shapes_.back()->getAabb(btTransform::getIdentity(), low, high);
    const btVector3 extent = high - low;
    const btScalar smallest = std::min(extent.x(), std::min(extent.y(), extent.z()));
    body_->setCcdMotionThreshold(btScalar(0.25) * smallest);
    body_->setCcdSweptSphereRadius(btScalar(0.2) * smallest);
  }
  if (fixed_)
    body_->setCollisionFlags(body_->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
}

RigidObject::~RigidObject()
{
  if (world_)
    world_->removeRigidBody(body_.get());
}

void RigidObject::addToWorld(btDiscreteDynamicsWorld* world)
{
  world_ = world;
  if (fixed_)
    world->addRigidBody(body_.get());
  else
    world->addRigidBody(body_.get(), int(btBroadphaseProxy::DefaultFilter) | kMovableObjectGroup,
                        int(btBroadphaseProxy::AllFilter));
}

Eigen::Isometry3d RigidObject::pose() const
{
  return toEigen(body_->getWorldTransform()) * object_T_body_.inverse();
}

void RigidObject::setPose(const Eigen::Isometry3d& pose)
{
  body_->setWorldTransform(toBullet(pose * object_T_body_));
  body_->setInterpolationWorldTransform(body_->getWorldTransform());
  body_->clearForces();
  setVelocity(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

Eigen::Vector3d RigidObject::linearVelocity() const
{
  return toEigen(body_->getLinearVelocity());
}

Eigen::Vector3d RigidObject::angularVelocity() const
{
  return toEigen(body_->getAngularVelocity());
}

Eigen::Vector3d RigidObject::pointVelocity(const Eigen::Vector3d& point) const
{
  const btVector3 arm = toBullet(Eigen::Vector3d(pose() * point)) - body_->getCenterOfMassPosition();
  return toEigen(body_->getVelocityInLocalPoint(arm));
}

void RigidObject::setVelocity(const Eigen::Vector3d& linear, const Eigen::Vector3d& angular)
{
  if (fixed_)
    return;
  body_->setLinearVelocity(toBullet(linear));
  body_->setAngularVelocity(toBullet(angular));
  // Forced: Bullet takes a body whose bounds overflowed out of the simulation for good (DISABLE_SIMULATION).
  body_->forceActivationState(ACTIVE_TAG);
  body_->setDeactivationTime(0);
}

void RigidObject::applyWrench(const Eigen::Vector3d& point, const Eigen::Vector3d& force, const Eigen::Vector3d& torque)
{
  if (fixed_)
    return;
  const Eigen::Vector3d world_point = pose() * point;
  const btVector3& com = body_->getCenterOfMassPosition();
  body_->applyForce(toBullet(force), toBullet(world_point) - com);
  body_->applyTorque(toBullet(torque));
  body_->activate(true);
}
}  // namespace vrrw_physics
