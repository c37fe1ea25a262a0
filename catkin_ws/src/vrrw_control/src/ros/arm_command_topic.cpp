#include <std_msgs/String.h>
#include <vrrw_control/ros/arm_command_topic.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_control
{
ArmCommandTopic::ArmCommandTopic(ros::NodeHandle& nh, ArmController& arm, ArmActionServer& server,
                                 const RobotHardware& hardware, const ArmActionServer::Options& options,
                                 bool real_mode)
  : arm_(arm)
  , server_(server)
  , hw_(hardware)
  , clock_(options.clock)
  , origin_(options.clock_origin)
  , real_mode_(real_mode)
  , name_(nh.getNamespace() + "/arm_controller/command")
  , command_(nh.subscribe("arm_controller/command", 100, &ArmCommandTopic::onCommand, this,
                          ros::TransportHints().tcpNoDelay()))
  , errors_(nh.advertise<std_msgs::String>("arm_controller/errors", 100))
{
}

void ArmCommandTopic::reject(const std::string& why)
{
  ROS_WARN_STREAM(name_ << ": rejected: " << why);
  std_msgs::String msg;
  msg.data = "command: " + why;
  errors_.publish(msg);
}

void ArmCommandTopic::onCommand(const trajectory_msgs::JointTrajectory& msg)
{
  if (real_mode_)
    return reject("not available in real mode: send a FollowJointTrajectory goal");
  if (!hw_.ready())
    return reject(hw_.fault());
  const ros::Time now = clock_();
  if (msg.points.empty())
  {
    server_.preempt("stopped by an empty trajectory on arm_controller/command");
    arm_.stop(toTime(now));
    return;
  }
  const ros::Time start = msg.header.stamp.isZero() ? now : msg.header.stamp;
  const auto plan = arm_.plan(vrrw_trajectory::fromMsg(msg), toTime(start), toTime(now));
  if (!plan.validation.ok())
    return reject(plan.validation.message);
  server_.preempt("preempted by a trajectory on arm_controller/command");
  arm_.start(plan, Tolerances::uniform(arm_.joints().size(), 0.0, 0.0, 0.0, 0.0), toTime(now));
}
}  // namespace vrrw_control
