#pragma once
// The client side of a robot's controllers for the command-line tools (./vrrw send, move, plan): plan through
// /<robot>/plan, follow a trajectory, move the gripper, with progress and results as lines on a stream.
// Ctrl-C (requestStop) cancels the goal it started; a controller that goes away mid-goal is named, not waited for.
#include <atomic>
#include <ostream>
#include <stdexcept>
#include <string>
#include <trajectory_msgs/JointTrajectory.h>
#include <vector>
#include <vrrw_msgs/Plan.h>

namespace vrrw_common
{
class Options;
}

namespace vrrw_control
{
/// \brief A failure while running (exit 1); what() is one line naming the action or service.
class ArmClientError : public std::runtime_error
{
public:
  explicit ArmClientError(const std::string& what) : std::runtime_error(what) {}
};

/// \brief How long the client waits, in wall seconds (the workspace may run on simulated time).
struct ArmClientLimits
{
  double server_wait = 5.0;   ///< for the action server to connect
  double gone_after = 2.0;    ///< a server unseen this long mid-goal is gone (a controller beats at 20 Hz)
  double cancel_wait = 5.0;   ///< for the result of a goal cancelled by Ctrl-C
  double result_slack = 60.0; ///< a goal without a result this long after its trajectory's end is given up
};

/// \brief What became of a goal; exit code 0 when it succeeded.
struct GoalOutcome
{
  std::string state;  ///< actionlib's SUCCEEDED, ABORTED, REJECTED, PREEMPTED, ...
  std::string text;   ///< the controller's reason
  bool interrupted = false;
  int exitCode() const { return state == "SUCCEEDED" && !interrupted ? 0 : 1; }
};

class ArmClient
{
public:
  /// \brief For \a robot of the running workspace (its /scene/robots/<robot> parameters); prints to \a out.
  ArmClient(const std::string& robot, std::ostream& out, ArmClientLimits limits = ArmClientLimits());

  /// \brief The arm joints in /scene/robots/<robot>/arm_joints order.
  const std::vector<std::string>& armJoints() const { return arm_joints_; }

  /// \brief Plans through /<robot>/plan and prints one line (time, points, path length); throws ArmClientError
  /// with the planner's message when it fails.
  trajectory_msgs::JointTrajectory plan(const vrrw_msgs::Plan::Request& request);

  /// \brief Executes \a trajectory on the arm controller with a progress line every 0.25 s and the result.
  GoalOutcome follow(const trajectory_msgs::JointTrajectory& trajectory);

  /// \brief Moves the gripper to \a position with \a effort (0: the controller's default); prints the result
  /// and the controller's reason when it refuses.
  GoalOutcome grip(double position, double effort);

  /// \brief Asks the goal in flight to stop: its goal is cancelled (safe from a signal handler).
  static void requestStop() { stop_requested_ = true; }

private:
  template <class Client>
  GoalOutcome waitFor(Client& client, const std::string& action, double expected_seconds);

  const std::string robot_;
  std::ostream& out_;
  const ArmClientLimits limits_;
  std::vector<std::string> arm_joints_;
  static std::atomic<bool> stop_requested_;  ///< set by a signal handler, read by the waiting loop
};

/// \brief The /<robot>/plan request of `--joints q1,..,qn` (in \a arm_joints order) or `--pose x,y,z,qx,qy,qz,qw
/// [--frame F]`, and `--seed N`; throws vrrw_common::OptionError naming the option.
vrrw_msgs::Plan::Request planRequest(const vrrw_common::Options& options, const std::vector<std::string>& arm_joints);

/// \brief "N points over D s, max joint speed V rad/s (joint)": what a planned trajectory is, in one line.
std::string trajectorySummary(const trajectory_msgs::JointTrajectory& trajectory);
}  // namespace vrrw_control
