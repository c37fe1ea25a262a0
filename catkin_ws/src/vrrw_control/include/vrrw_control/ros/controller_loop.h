#pragma once
// controller_node's loop: one robot's controllers on a FakeRobot (fake mode: state = command; real mode: a goal
// is previewed on it and relayed to the real arm's driver), cycled on the ROS clock.
#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/ros/robot_controllers.h>

namespace vrrw_control
{
class ControllerLoop
{
public:
  /// \brief The robot \a name's controllers (description from the scene or robot_description), at its initial
  /// positions; waits for a simulated clock's first tick. Throws ControlError for a robot it cannot drive.
  ControllerLoop(ros::NodeHandle& nh, ros::NodeHandle& pnh, const std::string& name, const std::string& mode,
                 double rate_hz);

  /// \brief The control loop: read, update, write, publish, every period of the ROS clock, until shutdown.
  void spin();

private:
  void publishStates(const ros::Time& now);
  /// Sleeps until `next` on the ROS clock, but at most 20 ms of wall time: when a simulated clock stops, the
  /// node still answers goals.
  void sleepUntil(const ros::Time& next) const;

  double period_;  ///< s of the ROS clock between cycles
  std::vector<std::string> joints_;
  std::unique_ptr<RobotControllers> controllers_;
  ros::Publisher states_, global_states_;
  sensor_msgs::JointState msg_;
};
}  // namespace vrrw_control
