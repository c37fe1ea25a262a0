#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <string>
#include <vrrw_kinematics/collision_world.h>

namespace vrrw_interaction
{
/// \brief The point of a body a hand takes hold of.
struct GrabTarget
{
  std::string body;                      ///< a robot link or an object name
  std::string robot;                     ///< the link's robot; "" for an object
  bool object = false;
  Eigen::Vector3d point_in_body = Eigen::Vector3d::Zero();   ///< in the link's (URDF) or the object's frame
  Eigen::Vector3d point_in_world = Eigen::Vector3d::Zero();
  double distance = 0.0;                 ///< m from the hand to the surface; 0 inside
};

/// \brief Which bodies a hand may take (say, not the table or a robot's fixed base).
using Grabbable = std::function<bool(const vrrw_kinematics::CollisionBody&)>;

/// \brief The body of `world` at `state` nearest `point` within `max_distance` (m), and its surface point
/// nearest `point` (the point itself when inside). Primitives exactly; meshes by their bounding sphere.
std::optional<GrabTarget> nearestBody(const vrrw_kinematics::CollisionWorld& world, const Eigen::VectorXd& state,
                                      const Eigen::Vector3d& point, double max_distance, const Grabbable& grabbable);

/// \brief Distance from `point` (world) to one element at `element_pose`; `closest` gets its nearest point.
double elementDistance(const vrrw_kinematics::CollisionElement& element, const Eigen::Isometry3d& element_pose,
                       const Eigen::Vector3d& point, Eigen::Vector3d& closest);
}  // namespace vrrw_interaction
