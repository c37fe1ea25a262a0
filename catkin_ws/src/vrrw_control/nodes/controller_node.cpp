// controller_node: FollowJointTrajectory and GripperCommand servers of one robot, in its namespace.
// Reads parameters, builds the hardware (fake | physics | real) and wires the library to ROS.
#include <cmath>
#include <memory>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/arm_action_server.h>
#include <vrrw_control/fake_robot.h>
#include <vrrw_control/gripper_action_server.h>
#include <vrrw_control/physics_robot.h>
#include <vrrw_control/real_robot.h>
#include <vrrw_control/ros_drive_link.h>
#include <vrrw_scene/robot_config.h>
#include <vrrw_scene/scene_loader.h>
#include <urdf_parser/urdf_parser.h>

using namespace vrrw_control;

namespace
{
/// What the node needs to know of its robot: from the scene (~scene) or from parameters.
struct RobotDescription
{
  std::string urdf;
  std::vector<std::string> arm_joints;
  std::string gripper_joint;
  std::map<std::string, double> initial;
  std::map<std::string, double> acceleration_limits;
};

RobotDescription describe(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name)
{
  RobotDescription d;
  std::string scene_name;
  if (pnh.getParam("scene", scene_name))
  {
    const auto scene = vrrw_scene::loadScene(scene_name);
    const auto* robot = scene.robot(name);
    if (!robot)
      throw std::runtime_error("~scene " + scene_name + ": robot " + name + ": not in the scene");
    d = { scene.urdf, robot->arm_joints, robot->gripper_joints.empty() ? "" : robot->gripper_joints.front(),
          robot->initial_positions, robot->acceleration_limits };
  }
  else
  {
    std::string key;
    if (!nh.searchParam("robot_description", key) || !nh.getParam(key, d.urdf))
      throw std::runtime_error("robot_description: parameter not set (and no ~scene)");
    const std::string p = name + "_";
    d.arm_joints = { p + "shoulder_pan_joint", p + "shoulder_lift_joint", p + "elbow_joint",
                     p + "wrist_1_joint",      p + "wrist_2_joint",       p + "wrist_3_joint" };
    pnh.getParam("arm_joints", d.arm_joints);
    const auto model = urdf::parseURDF(d.urdf);
    d.gripper_joint = model && model->getJoint(p + "finger_joint") ? p + "finger_joint" : "";
    std::string config_file;
    if (pnh.getParam("config_file", config_file))
      d.acceleration_limits = vrrw_scene::loadAccelerationLimits(config_file, p);
  }
  pnh.getParam("gripper_joint", d.gripper_joint);
  std::vector<double> initial;
  if (pnh.getParam("initial_positions", initial))
    for (size_t j = 0; j < initial.size() && j < d.arm_joints.size(); ++j)
      d.initial[d.arm_joints[j]] = initial[j];
  return d;
}

std::string lastComponent(const std::string& ns)
{
  const auto slash = ns.find_last_of('/');
  return slash == std::string::npos ? ns : ns.substr(slash + 1);
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "controller_node");
  ros::NodeHandle nh, pnh("~");
  const std::string name = pnh.param<std::string>("robot", lastComponent(nh.getNamespace()));
  const std::string mode = pnh.param<std::string>("mode", "fake");
  const double rate_hz = pnh.param("rate", mode == "physics" ? 1000.0 : 100.0);  // physics: its 1 ms step
  if (mode != "fake" && mode != "physics" && mode != "real")
  {
    ROS_FATAL_STREAM("~mode: '" << mode << "' is not one of fake, physics, real");
    return 2;
  }
  if (!(rate_hz > 0.0 && rate_hz <= 1000.0))
  {
    ROS_FATAL_STREAM("~rate: " << rate_hz << " Hz outside (0, 1000]");
    return 2;
  }

  RobotDescription robot;
  std::vector<JointLimits> limits;
  try
  {
    robot = describe(nh, pnh, name);
    limits = loadJointLimits(robot.urdf, robot.arm_joints, robot.acceleration_limits);
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM(e.what());
    return 2;
  }

  std::vector<std::string> joints = robot.arm_joints;
  if (!robot.gripper_joint.empty())
    joints.push_back(robot.gripper_joint);
  std::unique_ptr<RosDriveLink> link;
  std::unique_ptr<RobotHardware> hw;
  if (mode == "physics")
  {
    link = std::make_unique<RosDriveLink>(nh, "drive_targets", "joint_states");
    hw = std::make_unique<PhysicsRobot>(joints, *link);
  }
  else
    hw = std::make_unique<FakeRobot>(joints);
  std::vector<double> start(joints.size(), 0.0);
  for (size_t j = 0; j < joints.size(); ++j)
    if (robot.initial.count(joints[j]))
      start[j] = robot.initial.at(joints[j]);
  hw->reset(start);

  ValidationOptions gate;
  gate.start_tolerance = pnh.param("start_tolerance", gate.start_tolerance);
  gate.insert_blend = mode != "real" && pnh.param("insert_blend", false);
  std::vector<double> decel;
  const double stop_decel = pnh.param("stop_deceleration", 3.0);
  for (const auto& l : limits)
    decel.push_back(std::isfinite(l.max_acceleration) ? l.max_acceleration : stop_decel);
  ArmController arm(*hw, robot.arm_joints, TrajectoryValidator(limits, gate), decel);

  while (ros::ok() && ros::Time::now().isZero())
    ros::WallDuration(0.01).sleep();
  ArmActionServer::Options arm_options;
  arm_options.clock_origin = ros::Time::now();
  arm_options.defaults = Tolerances::uniform(robot.arm_joints.size(), pnh.param("path_tolerance", 0.0),
                                             pnh.param("goal_tolerance", 0.01),
                                             pnh.param("goal_velocity_tolerance", 0.0),
                                             pnh.param("goal_time", 1.0));
  arm_options.confirm_timeout = pnh.param("confirm_timeout", 120.0);
  std::unique_ptr<RealDriverRelay> relay;
  std::unique_ptr<RosDriveLink> real_link;
  std::unique_ptr<RealRobot> real;
  if (mode == "real")
  {
    const std::string prefix = pnh.param("strip_prefix", true) ? name + "_" : "";
    relay = std::make_unique<RealDriverRelay>(
        pnh.param<std::string>("real_driver_action", "scaled_pos_joint_traj_controller/follow_joint_trajectory"),
        prefix);
    const std::string real_states = pnh.param<std::string>("real_joint_states", "");
    if (!real_states.empty())
    {
      real_link = std::make_unique<RosDriveLink>(nh, "", real_states, prefix);
      real = std::make_unique<RealRobot>(robot.arm_joints, *real_link);
    }
  }
  ArmActionServer arm_server(nh, arm, *hw, arm_options, std::move(relay), real.get());

  std::unique_ptr<GripperController> gripper;
  std::unique_ptr<GripperActionServer> gripper_server;
  if (!robot.gripper_joint.empty())
  {
    GripperOptions g;
    const auto gl = loadJointLimits(robot.urdf, { robot.gripper_joint }).front();
    g.min_position = gl.min_position;
    g.max_position = gl.max_position;
    g.max_velocity = std::isfinite(gl.max_velocity) ? gl.max_velocity : g.max_velocity;
    g.min_duration = pnh.param("gripper_min_duration", g.min_duration);
    gripper = std::make_unique<GripperController>(*hw, robot.gripper_joint, g);
    gripper_server = std::make_unique<GripperActionServer>(nh, *gripper, arm_options.clock_origin,
                                                           pnh.param("allow_stalling", true));
  }

  ros::Publisher states, global_states;
  if (mode != "physics")
  {
    states = nh.advertise<sensor_msgs::JointState>("joint_states", 50);
    if (pnh.param("publish_global_joint_states", true))
      global_states = nh.advertise<sensor_msgs::JointState>("/joint_states", 50);
  }
  ROS_INFO_STREAM(nh.getNamespace() << ": controller up, mode " << mode << ", " << rate_hz << " Hz, arm "
                                    << robot.arm_joints.size() << " joints, gripper '" << robot.gripper_joint << "'");

  sensor_msgs::JointState msg;
  msg.name = joints;
  ros::Rate rate(rate_hz);
  ros::Time last = ros::Time::now();
  while (ros::ok())
  {
    ros::spinOnce();
    const ros::Time now = ros::Time::now();
    const double t = (now - arm_options.clock_origin).toSec(), period = (now - last).toSec();
    hw->read(t, period);
    if (real)
      real->read(t, period);
    if (hw->ready())
    {
      arm_server.update(now);
      if (gripper_server)
        gripper_server->update(now);
      hw->write(t, period);
    }
    if (states)
    {
      msg.header.stamp = now;
      msg.position = hw->state().positions;
      msg.velocity = hw->state().velocities;
      states.publish(msg);
      if (global_states)
        global_states.publish(msg);
    }
    last = now;
    rate.sleep();
  }
  return 0;
}
