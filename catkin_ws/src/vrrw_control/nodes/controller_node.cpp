// controller_node: FollowJointTrajectory, GripperCommand and the command topic of one robot, in its
// namespace, in fake or real mode (physics mode runs the same controllers inside physics_node: the
// vrrw_control/PhysicsController plugin). Reads parameters, builds the hardware, runs the control loop.
#include <memory>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/fake_robot.h>
#include <vrrw_control/ros/robot_controllers.h>

namespace vrrw_control
{
class ControllerNode
{
public:
  ControllerNode(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name, const std::string& mode,
                 double rate_hz)
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

  /// \brief The control loop: read, update, write, publish, every period of the ROS clock.
  void spin()
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

private:
  void publishStates(const ros::Time& now)
  {
    msg_.header.stamp = now;
    msg_.name = joints_;
    msg_.position = controllers_->hardware().state().positions;
    msg_.velocity = controllers_->hardware().state().velocities;
    states_.publish(msg_);
    if (global_states_)
      global_states_.publish(msg_);
  }

  /// Sleeps until `next` on the ROS clock, but at most 20 ms of wall time: when a simulated clock stops, the
  /// node still answers goals.
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

  double period_;
  std::vector<std::string> joints_;
  std::unique_ptr<RobotControllers> controllers_;
  ros::Publisher states_, global_states_;
  sensor_msgs::JointState msg_;
};
}  // namespace vrrw_control

int main(int argc, char** argv)
{
  ros::init(argc, argv, "controller_node");
  ros::NodeHandle nh, pnh("~");
  const std::string ns = nh.getNamespace();
  const std::string name = pnh.param<std::string>("robot", ns.substr(ns.find_last_of('/') + 1));
  const std::string mode = pnh.param<std::string>("mode", "fake");
  const double rate_hz = pnh.param("rate", 100.0);
  if (mode == "physics")
  {
    ROS_FATAL_STREAM("~mode: physics runs the controllers inside physics_node (its ~controller parameter: "
                     "vrrw_control/PhysicsController); controller_node runs fake and real");
    return 2;
  }
  if (mode != "fake" && mode != "real")
  {
    ROS_FATAL_STREAM("~mode: '" << mode << "' is not one of fake, real");
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
