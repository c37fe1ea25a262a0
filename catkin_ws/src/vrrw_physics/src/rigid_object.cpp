#include <vrrw_physics/mesh_shape.h>
#include <vrrw_physics/rigid_object.h>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <stdexcept>

namespace vrrw_physics
{
namespace
{
btVector3 bt(const Eigen::Vector3d& v)
{
  return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z()));
}

btTransform bt(const Eigen::Isometry3d& t)
{
  const Eigen::Quaterniond q(t.rotation());
  return btTransform(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
                     bt(Eigen::Vector3d(t.translation())));
}

Eigen::Isometry3d eigen(const btTransform& t)
{
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d e = Eigen::Isometry3d::Identity();
  e.translate(Eigen::Vector3d(t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z()));
  e.rotate(Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()));
  return e;
}

std::unique_ptr<btCollisionShape> makeShape(const vrrw_scene::Shape& shape, const std::string& object)
{
  using Type = vrrw_scene::Shape::Type;
  std::unique_ptr<btCollisionShape> result;
  switch (shape.type)
  {
    case Type::Box:
      result = std::make_unique<btBoxShape>(bt(Eigen::Vector3d(shape.box_size / 2)));
      break;
    case Type::Cylinder:
      result = std::make_unique<btCylinderShapeZ>(
          btVector3(btScalar(shape.radius), btScalar(shape.radius), btScalar(shape.length / 2)));
      break;
    case Type::Sphere:
      return std::make_unique<btSphereShape>(btScalar(shape.radius));
    case Type::Mesh:
      try
      {
        return loadConvexHull(resolveMeshPath(shape.mesh_path), shape.mesh_scale);
      }
      catch (const std::runtime_error& e)
      {
        throw std::runtime_error("object " + object + ": " + e.what());
      }
  }
  result->setMargin(btScalar(0.001));
  return result;
}
}  // namespace

RigidObject::RigidObject(const vrrw_scene::Object& object)
  : name_(object.name), fixed_(object.fixed || object.mass <= 0.0)
{
  if (object.collision.empty())
    throw std::runtime_error("object " + name_ + ": no collision shapes");
  if (!fixed_ && !object.inertia.allFinite())
    throw std::runtime_error("object " + name_ + ": inertia is not finite");
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
    shapes_.push_back(makeShape(shape, name_));
    compound->addChildShape(bt(body_T_object * shape.origin), shapes_.back().get());
  }
  btVector3 inertia = bt(principal);
  const btScalar mass = fixed_ ? btScalar(0) : btScalar(object.mass);
  if (!fixed_ && !given_inertia)
    compound->calculateLocalInertia(mass, inertia);
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, compound.get(), inertia);
  info.m_friction = btScalar(object.friction);
  info.m_restitution = btScalar(object.restitution);
  info.m_startWorldTransform = bt(object.pose * object_T_body_);
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
  world->addRigidBody(body_.get());
}

Eigen::Isometry3d RigidObject::pose() const
{
  return eigen(body_->getWorldTransform()) * object_T_body_.inverse();
}

void RigidObject::setPose(const Eigen::Isometry3d& pose)
{
  body_->setWorldTransform(bt(pose * object_T_body_));
  body_->setInterpolationWorldTransform(body_->getWorldTransform());
  setVelocity(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

Eigen::Vector3d RigidObject::linearVelocity() const
{
  const btVector3& v = body_->getLinearVelocity();
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

Eigen::Vector3d RigidObject::angularVelocity() const
{
  const btVector3& w = body_->getAngularVelocity();
  return Eigen::Vector3d(w.x(), w.y(), w.z());
}

Eigen::Vector3d RigidObject::pointVelocity(const Eigen::Vector3d& point) const
{
  const btVector3 arm = bt(Eigen::Vector3d(pose() * point)) - body_->getCenterOfMassPosition();
  const btVector3 v = body_->getVelocityInLocalPoint(arm);
  return Eigen::Vector3d(v.x(), v.y(), v.z());
}

void RigidObject::setVelocity(const Eigen::Vector3d& linear, const Eigen::Vector3d& angular)
{
  if (fixed_)
    return;
  body_->setLinearVelocity(bt(linear));
  body_->setAngularVelocity(bt(angular));
  body_->activate(true);
}

void RigidObject::applyWrench(const Eigen::Vector3d& point, const Eigen::Vector3d& force, const Eigen::Vector3d& torque)
{
  if (fixed_)
    return;
  const Eigen::Vector3d world_point = pose() * point;
  const btVector3& com = body_->getCenterOfMassPosition();
  body_->applyForce(bt(force), bt(world_point) - com);
  body_->applyTorque(bt(torque));
  body_->activate(true);
}
}  // namespace vrrw_physics
