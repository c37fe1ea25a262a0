#pragma once
#include <map>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/drive_link.h>

namespace vrrw_control
{
/// \brief DriveLink to the physics node: publishes sensor_msgs/JointState drive targets
/// (position + velocity) and keeps the newest value of every joint from its joint_states.
class RosDriveLink : public DriveLink
{
public:
  RosDriveLink(ros::NodeHandle& nh, const std::string& targets_topic, const std::string& states_topic);
  void sendTargets(const std::vector<std::string>& joints, const JointSample& targets, double time) override;
  bool latestState(const std::vector<std::string>& joints, JointSample& state, std::vector<double>& efforts) override;

private:
  struct Measured
  {
    double position = 0.0, velocity = 0.0, effort = 0.0;
  };
  void onJointStates(const sensor_msgs::JointState& msg);

  ros::Publisher targets_;
  ros::Subscriber states_;
  std::map<std::string, Measured> latest_;
  sensor_msgs::JointState out_;
};
}  // namespace vrrw_control
