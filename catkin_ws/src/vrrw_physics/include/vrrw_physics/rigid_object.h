#pragma once
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include <vrrw_scene/scene.h>

class btCollisionShape;
class btRigidBody;
class btDiscreteDynamicsWorld;

namespace vrrw_physics
{
/// \brief Broadphase group of movable objects: the only bodies the floor collides with.
constexpr int kMovableObjectGroup = 64;

/// \brief A scene object as one Bullet rigid body (static when the object is fixed).
///
/// The body frame sits at the centre of mass on the principal axes of inertia; collision shapes
/// (box, cylinder, sphere, convex hull of a mesh) are children of one compound shape.
class RigidObject
{
public:
  /// \brief Throws std::runtime_error "object NAME: reason" for an unusable description.
  explicit RigidObject(const vrrw_scene::Object& object);
  ~RigidObject();
  RigidObject(const RigidObject&) = delete;
  RigidObject& operator=(const RigidObject&) = delete;

  /// \brief Adds the body; a movable one joins kMovableObjectGroup besides Bullet's default group.
  void addToWorld(btDiscreteDynamicsWorld* world);

  const std::string& name() const { return name_; }
  bool fixed() const { return fixed_; }
  btRigidBody* body() const { return body_.get(); }
  /// \brief Pose of the object frame in the world.
  Eigen::Isometry3d pose() const;
  /// \brief Moves the object (velocities zeroed, body woken).
  void setPose(const Eigen::Isometry3d& pose);
  Eigen::Vector3d linearVelocity() const;
  Eigen::Vector3d angularVelocity() const;
  /// \brief World velocity of a point given in the object frame.
  Eigen::Vector3d pointVelocity(const Eigen::Vector3d& point) const;
  void setVelocity(const Eigen::Vector3d& linear, const Eigen::Vector3d& angular);
  /// \brief Applies a world force at a point given in the object frame plus a world torque (for this step).
  void applyWrench(const Eigen::Vector3d& point, const Eigen::Vector3d& force, const Eigen::Vector3d& torque);

private:
  std::string name_;
  bool fixed_;
  Eigen::Isometry3d object_T_body_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btRigidBody> body_;
  btDiscreteDynamicsWorld* world_ = nullptr;
};
}  // namespace vrrw_physics
