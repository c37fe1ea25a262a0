#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vrrw_common/ros/action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_srvs/Trigger.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_common
{
class PersistentServices;
}
namespace vrrw_physics
{
class LockstepClient;
}

namespace vrrw_demos
{
/// \brief How a goal ended, as the client saw it.
struct GoalOutcome
{
  std::string state;     ///< actionlib's (SUCCEEDED, ABORTED, REJECTED, PREEMPTED, ...), TIMEOUT or CANCELLED
  int error_code = 0;    ///< the action result's error_code (FollowJointTrajectory: 0 is success)
  std::string message;   ///< the result's error string / status text
  bool succeeded() const { return state == "SUCCEEDED"; }
  /// \brief "SUCCEEDED" or "ABORTED (error_code -4: ...)".
  std::string text() const;
};

/// \brief A gripper goal during an arm motion: \a time s after the motion's start.
struct TimedGripperGoal
{
  double time = 0.0;
  double position = 0.0;
  double effort = 0.0;  ///< N; 0: the gripper controller's default
};

/// \brief One arm motion as the controllers run it: the trajectory, when it starts, and the gripper goals
/// that belong to its timeline.
struct ArmMotion
{
  std::string name;  ///< what the operator reads: "to the recorded start", "move_to_pick"
  vrrw_trajectory::JointTrajectory trajectory;
  ros::Time start;   ///< header.stamp; zero: as the controller receives it
  std::vector<TimedGripperGoal> gripper_goals;
};

/// \brief Where a running motion is: its name, seconds since its start on the ROS clock, its duration,
/// and whether the real arm (not its simulation) is moving.
struct MotionProgress
{
  std::string name;
  double elapsed = 0.0, duration = 0.0;
  bool real = false;
};

/// \brief The controllers of one robot as a client drives them: its FollowJointTrajectory and
/// GripperCommand actions and its joint_states, in any mode. In real mode the controller runs each arm
/// goal in simulation first and holds it; this class confirms it (`confirm_real_execution`) once the
/// simulation ended, and the controller hands it to the real driver. This is the one real-mode goal path:
/// `./vrrw demos replay --mode real` and `./vrrw demo --real` (demo_relay) both go through it.
///
/// Waits are on the ROS clock (simulated time when /use_sim_time is set), with a guard on the wall
/// clock: when the ROS clock stops for kClockStalled, a wait gives up (the physics node died or paused).
/// In lockstep (holdSimulation) every goal is sent while the simulation waits and taken by the controller before
/// the client steps on; the gripper goals fall at their exact simulated times; so a run repeats bit for bit.
/// cancel() may be called from any thread (a signal's flag, polled): the running goals are cancelled.
class RobotControllers
{
public:
  using Progress = std::function<void(const MotionProgress&)>;
  static constexpr double kClockStalled = 10.0;  ///< wall s without the ROS clock moving
  static constexpr double kConfirmPeriod = 0.05; ///< s between confirmation attempts while it simulates

  /// \brief The controllers under /<robot>/; \a real: the controller runs in real mode (confirmations).
  /// \a interrupted (optional, e.g. set by a SIGINT handler) cancels like cancel() once it is true.
  RobotControllers(const std::string& robot, bool real, const std::atomic<bool>* interrupted = nullptr);
  ~RobotControllers();

  /// \brief Lockstep from here on: \a sim holds the simulation paused (the caller paused it); every wait steps it.
  void holdSimulation(vrrw_physics::LockstepClient& sim) { sim_ = &sim; }
  /// \brief The ROS clock; in lockstep the simulated time where the simulation waits.
  ros::Time now() const;

  /// \brief Waits up to \a seconds (wall) for both actions (and, real, the confirmation service); throws
  /// DemoError naming what does not answer.
  void connect(double seconds);
  /// \brief The arm's positions in \a joints order from the next joint_states; throws DemoError when none
  /// carries every joint within \a seconds.
  std::vector<double> measuredArm(const std::vector<std::string>& joints, double seconds);
  /// \brief Waits (at most \a seconds) until the measured arm is within \a tolerance of \a q: a real
  /// driver's joint_states may trail its result, and the controller's gate checks a goal's start against them.
  bool waitUntilAt(const std::vector<std::string>& joints, const std::vector<double>& q, double tolerance,
                   double seconds);

  /// \brief Runs one arm motion: sends it, sends its gripper goals when the ROS clock reaches them, in real
  /// mode confirms it once simulated, and waits for the result (at most the motion's duration plus
  /// \a slack s after the real arm started). \a progress is called about once a second.
  GoalOutcome runArm(const ArmMotion& motion, double slack, const Progress& progress = {});
  /// \brief One gripper goal, waited for up to \a seconds.
  GoalOutcome runGripper(double position, double effort, double seconds);

  /// \brief Cancels the goals this object runs (thread-safe; the running call returns CANCELLED).
  void cancel() { cancelled_ = true; }
  bool cancelled() const { return cancelled_ || (interrupted_ && *interrupted_); }
  /// \brief Sleeps \a seconds on the ROS clock; false when cancelled or the ROS clock stalled meanwhile.
  bool sleep(double seconds) { return pause(seconds); }
  const std::string& ns() const { return ns_; }

private:
  using ArmClient = vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction>;
  using GripperClient = vrrw_common::ActionClient<control_msgs::GripperCommandAction>;

  /// One confirmation attempt; true once the controller relayed the goal to the real driver.
  bool tryConfirm();
  /// Sleeps \a seconds on the ROS clock (lockstep: steps them); false when cancelled or the clock stalled
  /// (lockstep: a step failed) meanwhile.
  bool pause(double seconds);
  /// runArm in lockstep: steps to each gripper goal's time, sends it, then steps until every controller is idle.
  GoalOutcome runArmLockstep(const ArmMotion& motion, double slack, const Progress& progress);
  /// Lockstep: waits (wall clock, bounded) until \a client's goal left PENDING, so a step starts it.
  template <class Client>
  bool taken(Client& client);
  GoalOutcome armOutcome();

  std::string ns_;
  bool real_;
  const std::atomic<bool>* interrupted_;  ///< optional: a signal's flag, read only
  ArmClient arm_;
  GripperClient gripper_;
  std::string confirm_service_;
  std::unique_ptr<vrrw_common::PersistentServices> services_;  ///< the confirmation, every kConfirmPeriod
  vrrw_physics::LockstepClient* sim_ = nullptr;  ///< set by holdSimulation(): every wait steps it
  std::string confirm_message_;
  std::mutex state_mutex_;
  sensor_msgs::JointState latest_state_;  ///< PROTECTED BY state_mutex_
  std::atomic<std::size_t> states_seen_{ 0 };  ///< joint_states received; written under state_mutex_
  std::atomic<bool> cancelled_{ false };
  ros::Time last_clock_;           ///< the ROS time last seen moving ...
  ros::WallTime last_clock_wall_;  ///< ... and when, on the wall clock (the stall guard)
  /// The latest joint_states (a spinner must run: the tools run an AsyncSpinner). Declared last, so destroyed
  /// first: its shutdown waits for a running callback, which then finds every member it writes alive.
  ros::Subscriber states_;
};

/// \brief Asks the operator on \a out to type yes on \a in before a real robot moves; true if they did.
bool operatorSaysYes(const std::string& question, std::istream& in, std::ostream& out);
}  // namespace vrrw_demos
