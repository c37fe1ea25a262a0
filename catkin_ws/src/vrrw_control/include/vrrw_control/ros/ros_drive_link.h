#pragma once
#include <map>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <vrrw_control/drive_link.h>

namespace vrrw_control
{
/// \brief DriveLink to a real robot's driver: keeps the newest value of every joint of its joint_states.
class RosDriveLink : public DriveLink
{
public:
  /// \brief `name_prefix` is put before every incoming joint name (a real driver reports
  /// `shoulder_pan_joint` for our `ur5e_shoulder_pan_joint`).
  RosDriveLink(ros::NodeHandle& nh, const std::string& states_topic, const std::string& name_prefix = "");
  bool latestState(const std::vector<std::string>& joints, JointSample& state, std::vector<double>& efforts) override;

private:
  struct Measured
  {
    double position = 0.0, velocity = 0.0, effort = 0.0;
  };
  void onJointStates(const sensor_msgs::JointState& msg);

  ros::Subscriber states_;
  std::string prefix_;
  std::map<std::string, Measured> latest_;
};
}  // namespace vrrw_control
