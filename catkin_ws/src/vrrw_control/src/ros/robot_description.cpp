#include <urdf_parser/urdf_parser.h>
#include <vrrw_control/control_error.h>
#include <vrrw_control/ros/robot_description.h>
#include <vrrw_scene/robot_config.h>
#include <vrrw_scene/scene_loader.h>

namespace vrrw_control
{
namespace
{
RobotDescription fromScene(const vrrw_scene::Scene& scene, const std::string& name)
{
  const auto* robot = scene.robot(name);
  if (!robot)
    throw ControlError("scene " + scene.name + ": robot " + name + ": not in the scene");
  return { scene.urdf, robot->arm_joints, robot->gripper_joints.empty() ? "" : robot->gripper_joints.front(),
           robot->initial_positions, robot->acceleration_limits, robot->fingertip_lever_arm,
           robot->max_grip_force };
}

RobotDescription fromParameters(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name)
{
  RobotDescription d;
  std::string key;
  if (!nh.searchParam("robot_description", key) || !nh.getParam(key, d.urdf))
    throw ControlError("robot_description: parameter not set (and no ~scene)");
  const std::string p = name + "_";
  d.arm_joints = { p + "shoulder_pan_joint", p + "shoulder_lift_joint", p + "elbow_joint",
                   p + "wrist_1_joint",      p + "wrist_2_joint",       p + "wrist_3_joint" };
  pnh.getParam("arm_joints", d.arm_joints);
  const auto model = urdf::parseURDF(d.urdf);
  d.gripper_joint = model && model->getJoint(p + "finger_joint") ? p + "finger_joint" : "";
  std::string config_file;
  if (pnh.getParam("config_file", config_file))
    d.acceleration_limits = vrrw_scene::loadAccelerationLimits(config_file, p);
  pnh.getParam("gripper_lever_arm", d.gripper_lever_arm);
  pnh.getParam("max_grip_force", d.max_grip_force);
  return d;
}

RobotDescription withOverrides(RobotDescription d, ros::NodeHandle& pnh)
{
  pnh.getParam("gripper_joint", d.gripper_joint);
  std::vector<double> initial;
  if (pnh.getParam("initial_positions", initial))
    for (size_t j = 0; j < initial.size() && j < d.arm_joints.size(); ++j)
      d.initial[d.arm_joints[j]] = initial[j];
  return d;
}
}  // namespace

RobotDescription describeRobot(const vrrw_scene::Scene& scene, const std::string& name, ros::NodeHandle& pnh)
{
  return withOverrides(fromScene(scene, name), pnh);
}

RobotDescription describeRobot(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name)
{
  std::string scene_name;
  if (pnh.getParam("scene", scene_name))
    return withOverrides(fromScene(vrrw_scene::loadScene(scene_name), name), pnh);
  return withOverrides(fromParameters(nh, pnh, name), pnh);
}
}  // namespace vrrw_control
