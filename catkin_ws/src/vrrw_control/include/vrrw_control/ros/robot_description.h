#pragma once
// What a robot's controllers need to know of it: from a scene, or from parameters.
#include <map>
#include <ros/ros.h>
#include <string>
#include <vector>
#include <vrrw_scene/scene.h>

namespace vrrw_control
{
struct RobotDescription
{
  std::string urdf;
  std::vector<std::string> arm_joints;
  std::string gripper_joint;
  std::map<std::string, double> initial;
  std::map<std::string, double> acceleration_limits;
  double gripper_lever_arm = 0.0;  ///< m, fingertip_lever_arm of the gripper config; 0: unknown
  double max_grip_force = 0.0;     ///< N, max_grip_force of the gripper config; 0: unknown
};

/// \brief Robot `name` of `scene`, then the overrides of `pnh` (below). Throws std::runtime_error when the
/// scene has no such robot.
RobotDescription describeRobot(const vrrw_scene::Scene& scene, const std::string& name, ros::NodeHandle& pnh);

/// \brief Reads ~scene (a shipped name or a YAML) or, without it, /robot_description with ~arm_joints,
/// ~config_file, ~gripper_lever_arm, ~max_grip_force; ~gripper_joint and ~initial_positions override either.
/// Throws std::runtime_error naming the parameter.
RobotDescription describeRobot(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name);
}  // namespace vrrw_control
