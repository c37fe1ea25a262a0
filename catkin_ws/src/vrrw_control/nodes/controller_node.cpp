// controller_node: FollowJointTrajectory, GripperCommand and the command topic of one robot, in its
// namespace. Reads parameters, builds the hardware (fake | physics | real) and wires the library to ROS.
#include <cmath>
#include <memory>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <vrrw_control/arm_action_server.h>
#include <vrrw_control/arm_command_topic.h>
#include <vrrw_control/fake_robot.h>
#include <vrrw_control/gripper_action_server.h>
#include <vrrw_control/physics_robot.h>
#include <vrrw_control/real_robot.h>
#include <vrrw_control/ros_drive_link.h>

#include "robot_description.h"

namespace vrrw_control
{
class ControllerNode
{
public:
  ControllerNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name, const std::string& mode,
                 double rate_hz)
    : nh_(nh), name_(name), mode_(mode), period_(1.0 / rate_hz), robot_(describeRobot(nh, pnh, name))
  {
    makeHardware(pnh);
    makeArm(pnh);
    makeGripper(pnh);
    if (mode_ != "physics")
    {
      states_ = nh.advertise<sensor_msgs::JointState>("joint_states", 50);
      if (pnh.param("publish_global_joint_states", true))
        global_states_ = nh.advertise<sensor_msgs::JointState>("/joint_states", 50);
    }
    free_drive_ = nh.subscribe<std_msgs::Bool>("free_drive_active", 1, [this](const std_msgs::BoolConstPtr& msg) {
      arm_server_->setFreeDrive(msg->data, ros::Time::now());
    });
    ROS_INFO_STREAM(nh.getNamespace() << ": controller up, mode " << mode_ << ", " << rate_hz << " Hz, arm "
                                      << robot_.arm_joints.size() << " joints, gripper '" << robot_.gripper_joint
                                      << "'");
  }

  /// \brief The control loop: read, update, write, publish, every period of the ROS clock.
  void spin()
  {
    ros::Time next = ros::Time::now();
    last_ = next;
    while (ros::ok())
    {
      ros::spinOnce();
      const ros::Time now = ros::Time::now();
      cycle(now);
      next += ros::Duration(period_);
      if (next < now)
        next = now + ros::Duration(period_);  // fell behind: do not try to catch up
      sleepUntil(next);
    }
  }

private:
  void makeHardware(ros::NodeHandle& pnh)
  {
    joints_ = robot_.arm_joints;
    if (!robot_.gripper_joint.empty())
      joints_.push_back(robot_.gripper_joint);
    if (mode_ == "physics")
    {
      link_ = std::make_unique<RosDriveLink>(nh_, "drive_targets", "joint_states");
      hw_ = std::make_unique<PhysicsRobot>(joints_, *link_, pnh.param("state_timeout", 1.0));
    }
    else
      hw_ = std::make_unique<FakeRobot>(joints_);
    std::vector<double> start(joints_.size(), 0.0);
    for (size_t j = 0; j < joints_.size(); ++j)
      if (robot_.initial.count(joints_[j]))
        start[j] = robot_.initial.at(joints_[j]);
    hw_->reset(start);
  }

  void makeArm(ros::NodeHandle& pnh)
  {
    const auto limits = loadJointLimits(robot_.urdf, robot_.arm_joints, robot_.acceleration_limits);
    ValidationOptions gate;
    gate.start_tolerance = pnh.param("start_tolerance", gate.start_tolerance);
    ArmController::Options options;
    options.splice = mode_ != "real" && pnh.param("insert_blend", true);
    const double stop_deceleration = pnh.param("stop_deceleration", 3.0);
    for (const auto& l : limits)
      options.stop_deceleration.push_back(std::isfinite(l.max_acceleration) ? l.max_acceleration : stop_deceleration);
    arm_ = std::make_unique<ArmController>(*hw_, robot_.arm_joints, TrajectoryValidator(limits, gate), options);

    while (ros::ok() && ros::Time::now().isZero())  // a simulated clock: wait for its first tick
      ros::WallDuration(0.01).sleep();
    server_options_.clock_origin = ros::Time::now();
    server_options_.defaults = Tolerances::uniform(
        robot_.arm_joints.size(), pnh.param("path_tolerance", 0.0), pnh.param("goal_tolerance", 0.01),
        pnh.param("goal_velocity_tolerance", 0.0), pnh.param("goal_time", 1.0));
    server_options_.confirm_timeout = pnh.param("confirm_timeout", 120.0);
    server_options_.queue_size = pnh.param("action_queue_size", server_options_.queue_size);
    std::unique_ptr<RealDriverRelay> relay;
    if (mode_ == "real")
      relay = makeRealRelay(pnh);
    arm_server_ = std::make_unique<ArmActionServer>(nh_, *arm_, *hw_, server_options_, std::move(relay), real_.get());
    command_ = std::make_unique<ArmCommandTopic>(nh_, *arm_, *arm_server_, *hw_, server_options_.clock_origin,
                                                 mode_ == "real");
  }

  std::unique_ptr<RealDriverRelay> makeRealRelay(ros::NodeHandle& pnh)
  {
    const std::string prefix = pnh.param("strip_prefix", true) ? name_ + "_" : "";
    const std::string real_states = pnh.param<std::string>("real_joint_states", "");
    if (!real_states.empty())
    {
      real_link_ = std::make_unique<RosDriveLink>(nh_, "", real_states, prefix);
      real_ = std::make_unique<RealRobot>(robot_.arm_joints, *real_link_);
    }
    return std::make_unique<RealDriverRelay>(
        pnh.param<std::string>("real_driver_action", "scaled_pos_joint_traj_controller/follow_joint_trajectory"),
        prefix);
  }

  void makeGripper(ros::NodeHandle& pnh)
  {
    if (robot_.gripper_joint.empty())
      return;
    GripperOptions g;
    const auto limits = loadJointLimits(robot_.urdf, { robot_.gripper_joint }).front();
    g.min_position = limits.min_position;
    g.max_position = limits.max_position;
    g.max_velocity = std::isfinite(limits.max_velocity) ? limits.max_velocity : g.max_velocity;
    g.min_duration = pnh.param("gripper_min_duration", g.min_duration);
    g.lever_arm = robot_.gripper_lever_arm;
    g.max_grip_force = robot_.max_grip_force;
    gripper_ = std::make_unique<GripperController>(*hw_, robot_.gripper_joint, g);
    gripper_server_ = std::make_unique<GripperActionServer>(nh_, *gripper_, *hw_, server_options_.clock_origin,
                                                            pnh.param("allow_stalling", true), server_options_.queue_size);
  }

  void cycle(const ros::Time& now)
  {
    const double t = (now - server_options_.clock_origin).toSec(), period = (now - last_).toSec();
    hw_->read(t, period);
    if (real_)
      real_->read(t, period);
    if (!hw_->ready())
    {
      arm_server_->suspend(hw_->fault());
      if (gripper_server_)
        gripper_server_->suspend(hw_->fault());
    }
    else if (now > last_ || !started_)
    {
      arm_server_->update(now);
      if (gripper_server_)
        gripper_server_->update(now);
      hw_->write(t, period);
      started_ = true;
    }
    if (states_ && now > last_)
      publishStates(now);
    last_ = now;
  }

  void publishStates(const ros::Time& now)
  {
    msg_.header.stamp = now;
    msg_.name = joints_;
    msg_.position = hw_->state().positions;
    msg_.velocity = hw_->state().velocities;
    states_.publish(msg_);
    if (global_states_)
      global_states_.publish(msg_);
  }

  /// Sleeps until `next` on the ROS clock, but at most 20 ms of wall time: when a simulated clock
  /// stops (its physics node died or paused), the node still answers goals and notices stale states.
  void sleepUntil(const ros::Time& next) const
  {
    if (!ros::Time::isSimTime())
    {
      const ros::Duration left = next - ros::Time::now();
      if (left > ros::Duration(0))
        left.sleep();
      return;
    }
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(0.02);
    const ros::WallDuration poll(std::min(0.5 * period_, 0.001));
    while (ros::ok() && ros::Time::now() < next && ros::WallTime::now() < give_up)
      poll.sleep();
  }

  ros::NodeHandle& nh_;
  std::string name_, mode_;
  double period_;
  RobotDescription robot_;
  std::vector<std::string> joints_;
  std::unique_ptr<RosDriveLink> link_, real_link_;
  std::unique_ptr<RobotHardware> hw_;
  std::unique_ptr<RealRobot> real_;
  std::unique_ptr<ArmController> arm_;
  ArmActionServer::Options server_options_;
  std::unique_ptr<ArmActionServer> arm_server_;
  std::unique_ptr<ArmCommandTopic> command_;
  std::unique_ptr<GripperController> gripper_;
  std::unique_ptr<GripperActionServer> gripper_server_;
  ros::Publisher states_, global_states_;
  ros::Subscriber free_drive_;
  sensor_msgs::JointState msg_;
  ros::Time last_;
  bool started_ = false;
};
}  // namespace vrrw_control

int main(int argc, char** argv)
{
  ros::init(argc, argv, "controller_node");
  ros::NodeHandle nh, pnh("~");
  const std::string ns = nh.getNamespace();
  const std::string name = pnh.param<std::string>("robot", ns.substr(ns.find_last_of('/') + 1));
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
  try
  {
    vrrw_control::ControllerNode node(nh, pnh, name, mode, rate_hz);
    node.spin();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM(e.what());
    return 2;
  }
  return 0;
}
