#pragma once
#include <actionlib/server/action_server.h>
#include <ros/ros.h>

namespace vrrw_control
{
/// \brief actionlib's ActionServer whose status heartbeat the control cycle sends, on the controllers' clock (the
/// simulation's in physics mode), instead of actionlib's timer (wall clock in physics_node): a lockstep run
/// sends the same heartbeats each time. Build it with actionParameters (its timer off).
template <class Action>
class ClockedActionServer : public actionlib::ActionServer<Action>
{
public:
  ClockedActionServer(ros::NodeHandle nh, const std::string& name, double period,
                      boost::function<void(actionlib::ServerGoalHandle<Action>)> goal,
                      boost::function<void(actionlib::ServerGoalHandle<Action>)> cancel)
    : actionlib::ActionServer<Action>(nh, name, goal, cancel, false), period_(period)
  {
  }

  /// \brief Called every cycle: the status of every goal once `period` s passed since the last.
  void heartbeat(const ros::Time& now)
  {
    if (period_ <= 0.0 || (!sent_.isZero() && (now - sent_).toSec() < period_ - 1e-9))
      return;
    publishStatus();
    sent_ = now;
  }

private:
  // actionlib's own is private; its base's declaration (a virtual call) reaches it
  using actionlib::ActionServerBase<Action>::publishStatus;

  double period_;
  ros::Time sent_;
};
}  // namespace vrrw_control
