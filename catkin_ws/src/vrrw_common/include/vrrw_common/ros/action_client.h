#pragma once
// A SimpleActionClient that gets its server's status also when its process already follows that server.
#include <actionlib/client/simple_action_client.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <string>

namespace vrrw_common
{
namespace detail
{
/// The client's own callback queue and a node handle on it, made before the client (a base, so first).
struct OwnQueue
{
  OwnQueue() { node.setCallbackQueue(&queue); }
  ros::CallbackQueue queue;
  ros::NodeHandle node;
};
}  // namespace detail

/// \brief actionlib::SimpleActionClient whose callbacks run on a queue of its own, served from when the client is
/// whole. actionlib's own spin thread runs before the client has its connection monitor: a client made in a process
/// that already subscribes the server's status gets the latched status at once, on that thread, and drops it;
/// it then counts as connected only at the next status. A server's heartbeat runs on ROS time, so while a lockstep
/// simulation waits that next status never comes (a skill's trials waited 10 s and gave up).
template <class Action>
class ActionClient : private detail::OwnQueue, public actionlib::SimpleActionClient<Action>
{
public:
  /// \brief `name`: the action's namespace, e.g. /ur5e/arm_controller/follow_joint_trajectory.
  explicit ActionClient(const std::string& name)
    : actionlib::SimpleActionClient<Action>(node, name, false), spinner_(1, &queue)
  {
    spinner_.start();
  }

private:
  ros::AsyncSpinner spinner_;
};
}  // namespace vrrw_common
