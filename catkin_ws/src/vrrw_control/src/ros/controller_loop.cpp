#include <vrrw_control/ros/controller_loop.h>

#include <algorithm>

#include <vrrw_control/fake_robot.h>

namespace vrrw_control
{
ControllerLoop::ControllerLoop(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name,
                               const std::string& mode, double rate_hz)
  : period_(1.0 / rate_hz)
{
  const RobotDescription robot = describeRobot(nh, pnh, name);
  joints_ = RobotControllers::joints(robot);
  auto hardware = std::make_unique<FakeRobot>(joints_);
  std::vector<double> start(joints_.size(), 0.0);
  for (size_t j = 0; j < joints_.size(); ++j)
    if (robot.initial.count(joints_[j]))
      start[j] = robot.initial.at(joints_[j]);
  hardware->reset(start);
  while (ros::ok() && ros::Time::now().isZero())  // a simulated clock: wait for its first tick
    ros::WallDuration(0.01).sleep();
  controllers_ = std::make_unique<RobotControllers>(nh, pnh, name, robot, mode, std::move(hardware),
                                                    [] { return ros::Time::now(); });
  states_ = nh.advertise<sensor_msgs::JointState>("joint_states", 50);
  if (pnh.param("publish_global_joint_states", true))
    global_states_ = nh.advertise<sensor_msgs::JointState>("/joint_states", 50);
  ROS_INFO_STREAM(nh.getNamespace() << ": controller up, mode " << mode << ", " << rate_hz << " Hz, arm "
                                    << robot.arm_joints.size() << " joints, gripper '" << robot.gripper_joint
                                    << "'");
}

void ControllerLoop::spin()
{
  ros::Time next = ros::Time::now(), last = next;
  while (ros::ok())
  {
    ros::spinOnce();
    const ros::Time now = ros::Time::now();
    if (now > last)
    {
      controllers_->cycle(now, (now - last).toSec());
      publishStates(now);
      last = now;
    }
    next += ros::Duration(period_);
    if (next < now)
      next = now + ros::Duration(period_);  // fell behind: do not try to catch up
    sleepUntil(next);
  }
}

void ControllerLoop::publishStates(const ros::Time& now)
{
  msg_.header.stamp = now;
  msg_.name = joints_;
  msg_.position = controllers_->hardware().state().positions;
  msg_.velocity = controllers_->hardware().state().velocities;
  states_.publish(msg_);
  if (global_states_)
    global_states_.publish(msg_);
}

void ControllerLoop::sleepUntil(const ros::Time& next) const
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
}  // namespace vrrw_control
