#include "collision_shape.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>

#include "bullet_conversions.h"
#include "mesh_shape.h"

namespace vrrw_physics
{
std::unique_ptr<btCollisionShape> makeCollisionShape(const vrrw_scene::Shape& shape)
{
  using Type = vrrw_scene::Shape::Type;
  std::unique_ptr<btCollisionShape> result;
  switch (shape.type)
  {
    case Type::Box:
      result = std::make_unique<btBoxShape>(toBullet(Eigen::Vector3d(shape.box_size / 2)));
      break;
    case Type::Cylinder:
      result = std::make_unique<btCylinderShapeZ>(
          btVector3(btScalar(shape.radius), btScalar(shape.radius), btScalar(shape.length / 2)));
      break;
    case Type::Sphere:
      // A sphere's margin is its radius: Bullet keeps it.
      return std::make_unique<btSphereShape>(btScalar(shape.radius));
    case Type::Mesh:
      return loadConvexHull(shape.mesh_path, shape.mesh_scale);
  }
  result->setMargin(btScalar(0.001));
  return result;
}
}  // namespace vrrw_physics
