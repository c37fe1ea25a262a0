#include <vrrw_control/ros/ros_drive_link.h>

namespace vrrw_control
{
RosDriveLink::RosDriveLink(ros::NodeHandle& nh, const std::string& states_topic, const std::string& name_prefix)
  : states_(nh.subscribe(states_topic, 10, &RosDriveLink::onJointStates, this, ros::TransportHints().tcpNoDelay()))
  , prefix_(name_prefix)
{
}

void RosDriveLink::onJointStates(const sensor_msgs::JointState& msg)
{
  for (size_t i = 0; i < msg.name.size() && i < msg.position.size(); ++i)
  {
    auto& m = latest_[prefix_ + msg.name[i]];
    m.position = msg.position[i];
    m.velocity = i < msg.velocity.size() ? msg.velocity[i] : 0.0;
    m.effort = i < msg.effort.size() ? msg.effort[i] : 0.0;
  }
}

bool RosDriveLink::latestState(const std::vector<std::string>& joints, JointSample& state, std::vector<double>& efforts)
{
  for (size_t j = 0; j < joints.size(); ++j)
  {
    const auto it = latest_.find(joints[j]);
    if (it == latest_.end())
      return false;
    state.positions[j] = it->second.position;
    state.velocities[j] = it->second.velocity;
    state.accelerations[j] = 0.0;
    efforts[j] = it->second.effort;
  }
  return true;
}
}  // namespace vrrw_control
