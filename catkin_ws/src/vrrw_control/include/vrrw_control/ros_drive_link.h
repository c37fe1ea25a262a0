#pragma once
#include <map>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/drive_link.h>

namespace vrrw_control
{
/// \brief DriveLink to the physics node: publishes sensor_msgs/JointState drive targets
/// (position + velocity; joints with a force limit in a second message whose `effort` carries it)
/// and keeps the newest value of every joint from its joint_states.
class RosDriveLink : public DriveLink
{
public:
  /// \brief `targets_topic` empty: measure only. `name_prefix` is put before every incoming joint
  /// name (a real driver reports `shoulder_pan_joint` for our `ur5e_shoulder_pan_joint`).
  RosDriveLink(ros::NodeHandle& nh, const std::string& targets_topic, const std::string& states_topic,
               const std::string& name_prefix = "");
  void sendTargets(const std::vector<std::string>& joints, const JointSample& targets,
                   const std::vector<double>& effort_limits, double time) override;
  bool latestState(const std::vector<std::string>& joints, JointSample& state, std::vector<double>& efforts) override;
  double stateAge() const override;

private:
  struct Measured
  {
    double position = 0.0, velocity = 0.0, effort = 0.0;
  };
  void onJointStates(const sensor_msgs::JointState& msg);

  ros::Publisher targets_;
  ros::Subscriber states_;
  std::string prefix_;
  std::map<std::string, Measured> latest_;
  ros::WallTime received_;  ///< zero until the first message
  sensor_msgs::JointState out_, limited_;
};
}  // namespace vrrw_control
