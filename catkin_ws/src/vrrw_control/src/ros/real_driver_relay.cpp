#include <vrrw_control/ros/real_driver_relay.h>

namespace vrrw_control
{
RealDriverRelay::RealDriverRelay(const std::string& action, const std::string& prefix)
  : action_(action), prefix_(prefix), client_(action, false)
{
}

RealDriverRelay::Goal RealDriverRelay::driverGoal(const Goal& validated) const
{
  Goal g = validated;
  g.trajectory.header.stamp = ros::Time(0);
  const auto strip = [&](std::string& name) {
    if (!prefix_.empty() && name.rfind(prefix_, 0) == 0)
      name = name.substr(prefix_.size());
  };
  for (auto& n : g.trajectory.joint_names)
    strip(n);
  for (auto& t : g.path_tolerance)
    strip(t.name);
  for (auto& t : g.goal_tolerance)
    strip(t.name);
  return g;
}

bool RealDriverRelay::connected() const { return client_.isServerConnected(); }

bool RealDriverRelay::send(const Goal& validated, Done done, Feedback feedback)
{
  if (!client_.isServerConnected())
    return false;
  client_.sendGoal(
      driverGoal(validated),
      [done](const actionlib::SimpleClientGoalState& state,
             const control_msgs::FollowJointTrajectoryResultConstPtr& r) {
        done(state, r ? *r : control_msgs::FollowJointTrajectoryResult());
      },
      actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction>::SimpleActiveCallback(),
      [feedback](const control_msgs::FollowJointTrajectoryFeedbackConstPtr& f) { feedback(*f); });
  return true;
}

void RealDriverRelay::cancel() { client_.cancelGoal(); }

std::string RealDriverRelay::prefixed(const std::string& joint) const
{
  return joint.rfind(prefix_, 0) == 0 ? joint : prefix_ + joint;
}
}  // namespace vrrw_control
