#pragma once
// A client that holds a lockstep physics node and advances it itself (/physics/pause, /physics/step): what a
// script, a test or an evaluation uses to get the same joint trajectories on every run, at any real-time factor.
#include <functional>
#include <ros/ros.h>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <vrrw_common/ros/clock.h>
#include <vrrw_common/ros/persistent_service.h>

namespace vrrw_physics
{
/// \brief A step the physics node refused or a call that did not come back; what() is one line naming the service.
class LockstepError : public std::runtime_error
{
public:
  explicit LockstepError(const std::string& what) : std::runtime_error(what) {}
};

/// \brief How a LockstepClient advances the simulation.
struct LockstepOptions
{
  /// simulated s per /physics/step call: after each, the observers catch up (caughtUp), so a subscriber's
  /// queue holds at most this much of the viewer-rate states (0.25 s at 100 Hz: 25 joint_states, about 60 tf
  /// messages, under tf2_ros' queue of 100)
  double slice = 0.25;
  /// the real-time factor of every step request: 0 the physics node's own (~rtf), a positive number, or infinity
  /// (as fast as the cores allow)
  double rtf = 0.0;
};

/// \brief Holds the simulation (pause) and advances it (step): the client acts while the simulation waits
/// (goals, set_object_pose, stamped operator input ahead of simulated time), then steps, so every action falls
/// at a deterministic simulated time. Paced or not is the physics node's real-time factor: stepping at rtf 1 takes
/// as long as the simulated time. Not thread-safe: one thread steps.
class LockstepClient
{
public:
  /// \brief `physics`: the physics node's name; calls go over `services` (persistent links).
  explicit LockstepClient(vrrw_common::PersistentServices& services, const std::string& physics = "/physics",
                          const LockstepOptions& options = LockstepOptions());

  /// \brief Waits up to `seconds` (wall clock) for the physics node's /step service.
  bool waitForPhysics(double seconds) const;
  /// \brief Holds the simulation where it is (a second pause changes nothing); throws LockstepError.
  void pause();
  /// \brief Lets it run on at its real-time factor.
  void unpause();
  /// \brief Whether the simulation is paused (a step request of 0 s is refused while it runs); throws
  /// LockstepError when another client's step request is running.
  bool paused();
  /// \brief The simulated time while it waits (no step).
  ros::Time now();
  /// \brief Advances `seconds` of simulated time (whole steps, in slices); the time reached.
  ros::Time step(double seconds);
  /// \brief Advances until every controller of the physics node is idle (no goal active), at least one step and
  /// at most `seconds`; true when they are idle.
  bool stepUntilIdle(double seconds);
  using StopObserver = std::function<void(const ros::Time&)>;
  /// \brief `observer` is called after every stop with the simulated time reached, before step() goes on or
  /// returns, in the order the observers were added: e.g. a wait until a subscriber has the state published
  /// there (the exact state at every stop), then samples taken from it. Returns its key for removeStopObserver.
  int addStopObserver(StopObserver observer);
  void removeStopObserver(int key);
  /// \brief The simulated time of the last answer.
  ros::Time time() const { return time_; }
  /// \brief Waits (at most 0.5 s of wall time) until this process' ROS clock reached time(): what it then
  /// stamps with the ROS clock (an actionlib goal) carries the instant the simulation waits at on every run.
  void awaitClock() const { vrrw_common::awaitClock(time_); }

private:
  /// One /physics/step call; true when every controller was idle at its end.
  bool call(double seconds, bool until_idle);

  vrrw_common::PersistentServices& services_;
  std::string physics_;
  LockstepOptions options_;
  std::vector<std::pair<int, StopObserver>> observers_;  ///< by key, in the order added
  int next_key_ = 0;
  ros::Time time_;
};

/// \brief Waits (wall clock, at most `seconds`) until `client`'s goal (an actionlib SimpleActionClient's) left PENDING: the controller took it, so it
/// is part of the simulation and a step starts it (a controller inside physics takes goals between steps and
/// every 10 ms while the simulation waits).
template <class ActionClient>
bool waitUntilAccepted(ActionClient& client, double seconds = 10.0)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
       ros::WallDuration(0.001).sleep())
    if (client.getState() != decltype(client.getState())::PENDING)
      return true;
  return false;
}

/// \brief Waits (wall clock, at most `seconds`) until `client`'s goal is done: after a step until idle its result
/// is on its way (actionlib's own waits count ROS time, which stands still while the simulation waits).
template <class ActionClient>
bool waitUntilDone(ActionClient& client, double seconds = 10.0)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds); ros::WallTime::now() < end;
       ros::WallDuration(0.001).sleep())
    if (client.getState().isDone())
      return true;
  return false;
}
}  // namespace vrrw_physics
