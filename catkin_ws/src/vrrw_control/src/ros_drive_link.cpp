#include <limits>
#include <vrrw_control/ros_drive_link.h>

namespace vrrw_control
{
RosDriveLink::RosDriveLink(ros::NodeHandle& nh, const std::string& targets_topic, const std::string& states_topic,
                           const std::string& name_prefix)
  : states_(nh.subscribe(states_topic, 10, &RosDriveLink::onJointStates, this, ros::TransportHints().tcpNoDelay()))
  , prefix_(name_prefix)
{
  if (!targets_topic.empty())
    targets_ = nh.advertise<sensor_msgs::JointState>(targets_topic, 10);
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
  received_ = ros::WallTime::now();
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

double RosDriveLink::stateAge() const
{
  return received_.isZero() ? std::numeric_limits<double>::infinity() : (ros::WallTime::now() - received_).toSec();
}

void RosDriveLink::sendTargets(const std::vector<std::string>& joints, const JointSample& targets,
                               const std::vector<double>& effort_limits, double)
{
  if (!targets_)
    return;
  // the physics node reads `effort` as one force limit per joint of the message (empty: configured
  // limits), so the joints with a limit of their own travel in a message of their own
  out_.name.clear(), out_.position.clear(), out_.velocity.clear();
  limited_.name.clear(), limited_.position.clear(), limited_.velocity.clear(), limited_.effort.clear();
  for (size_t j = 0; j < joints.size(); ++j)
  {
    const bool limited = effort_limits[j] > 0.0;
    auto& msg = limited ? limited_ : out_;
    msg.name.push_back(joints[j]);
    msg.position.push_back(targets.positions[j]);
    msg.velocity.push_back(targets.velocities[j]);
    if (limited)
      limited_.effort.push_back(effort_limits[j]);
  }
  out_.header.stamp = limited_.header.stamp = ros::Time::now();
  if (!out_.name.empty())
    targets_.publish(out_);
  if (!limited_.name.empty())
    targets_.publish(limited_);
}
}  // namespace vrrw_control
