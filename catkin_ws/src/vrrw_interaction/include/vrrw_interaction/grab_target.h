#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>
#include <vrrw_kinematics/collision_world.h>
#include <vrrw_scene/scene.h>

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

/// \brief The link a hand that touches `link` pulls on: `link` itself on the arm (and above it); for a link
/// that moves by a gripper joint, the link that gripper is mounted on (the first link above every gripper
/// joint). A person who takes a gripper by a finger moves the arm, not the finger (a Robotiq's linkage does not
/// back-drive), and a grip that holds a finger's orientation is stiffer than one physics step can carry on a
/// finger of a few grams (issue 21: the physics guard at 56 rad/s on a stretched arm).
std::string heldLink(const vrrw_kinematics::RobotModel& model, const std::string& link,
                     const std::vector<std::string>& arm_joints);

/// \brief What a hand may take hold of.
struct GrabRule
{
  double max_distance = 0.05;     ///< m from the hand to the body's surface
  std::set<std::string> robots;   ///< robots whose links a hand may take
  bool movable_objects = false;   ///< objects that are not fixed (in physics a spring moves them; never the table)
};

/// \brief What a hand closing at `point` takes: the nearest link of `rule.robots` or (with
/// rule.movable_objects) movable object within rule.max_distance, at its surface point nearest the hand. A
/// link is held by heldLink(), `point_in_body` in that link's frame.
std::optional<GrabTarget> handGrab(const vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Scene& scene,
                                   const Eigen::VectorXd& state, const Eigen::Vector3d& point, const GrabRule& rule);

/// \brief True when no robot link and no movable object is within `radius` of `point`: an open hand may
/// become a pushing sphere there (one that appeared inside a link would kick it; the table does not count).
bool clearOfMovingBodies(const vrrw_kinematics::CollisionWorld& world, const vrrw_scene::Scene& scene,
                         const Eigen::VectorXd& state, const Eigen::Vector3d& point, double radius);
}  // namespace vrrw_interaction
