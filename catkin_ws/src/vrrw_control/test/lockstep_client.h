#pragma once
// A test's hold on a lockstep physics node: pause, step, wait until a goal joined the simulation.
#include "ros_test_helpers.h"

#include <actionlib/client/simple_action_client.h>
#include <std_srvs/Empty.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/Step.h>

namespace vrrw_control_test
{
/// A client of a lockstep physics node that advances simulated time itself: it pauses the simulation, acts
/// while it waits (goals stamped at its time take effect there), then steps it.
class Lockstep
{
public:
  /// \brief `physics`: the physics node's name.
  explicit Lockstep(const std::string& physics = "/physics") : physics_(physics) {}
  bool waitForPhysics(double seconds = 30.0)
  {
    return ros::service::waitForService(physics_ + "/step", ros::Duration(seconds));  // wall clock inside
  }
  void pause()
  {
    std_srvs::Empty srv;
    vrrw_common::services().call(physics_ + "/pause", srv);
  }
  /// Advances `seconds` of simulated time (or until every controller is idle); the time reached.
  ros::Time step(double seconds, bool until_idle = false)
  {
    vrrw_physics::Step srv;
    srv.request.duration = seconds;
    srv.request.until_idle = until_idle;
    try
    {
      vrrw_common::services().call(physics_ + "/step", srv, 700.0);  // paced, a step may take its duration
    }
    catch (const vrrw_common::ServiceError& e)
    {
      ADD_FAILURE() << e.what();
    }
    EXPECT_TRUE(srv.response.success) << srv.response.message;
    last_idle_ = srv.response.idle;
    return srv.response.time;
  }
  /// The simulated time while it waits.
  ros::Time now() { return step(0.0); }
  bool idle() const { return last_idle_; }

private:
  std::string physics_;
  bool last_idle_ = true;
};

/// Waits (wall clock, bounded) until the server has taken the goal: it is then part of the simulation.
template <class Client>
bool waitAccepted(Client& client, double seconds = 10.0)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::WallTime::now() < end)
  {
    if (client.getState() != actionlib::SimpleClientGoalState::PENDING)
      return true;
    ros::WallDuration(0.002).sleep();
  }
  return false;
}
}  // namespace vrrw_control_test
