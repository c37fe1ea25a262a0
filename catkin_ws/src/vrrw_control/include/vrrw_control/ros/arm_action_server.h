#pragma once
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <functional>
#include <memory>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <vrrw_control/arm_controller.h>
#include <vrrw_control/ros/clocked_action_server.h>
#include <vrrw_control/ros/real_driver_relay.h>

namespace vrrw_control
{
/// \brief The FollowJointTrajectory action of one arm: gate, splicing (or, strict, preemption by a
/// stop), cancel with a smooth stop, feedback every control cycle, results with control_msgs error
/// codes. In real mode a goal first runs in simulation, then waits for `confirm_real_execution`
/// before the relay sends it. Every goal that reaches the server gets a result.
class ArmActionServer
{
public:
  using Action = control_msgs::FollowJointTrajectoryAction;
  using GoalHandle = actionlib::ServerGoalHandle<Action>;

  struct Options
  {
    Tolerances defaults;            ///< used where a goal leaves a tolerance at 0
    /// \brief The controllers' time now (ros::Time::now, or the simulation's between its steps).
    std::function<ros::Time()> clock = [] { return ros::Time::now(); };
    ros::Time clock_origin;         ///< maps to controller time 0 (keeps doubles small and exact)
    double confirm_timeout = 120.0;  ///< real mode: s to wait for the confirmation
    int queue_size = 10000;          ///< goals (and results) actionlib may queue: a burst's size
    double feedback_period = 0.0;    ///< s between feedback messages of a goal; 0: every control cycle
    double status_period = 0.2;      ///< s of controller time between status heartbeats (actionlib's 5 Hz)
  };

  /// \brief `relay` non-null selects real mode. `real` (optional, real mode) measures the real arm:
  /// whenever no goal is previewed in simulation the virtual arm adopts its state, so the preview
  /// and the gate start from where the real arm is, also after a relayed goal ended elsewhere.
  ArmActionServer(ros::NodeHandle& nh, ArmController& arm, const RobotHardware& hardware, Options options,
                  std::unique_ptr<RealDriverRelay> relay, const RobotHardware* real = nullptr);

  /// \brief One control cycle at `now`; between hardware read and write.
  void update(const ros::Time& now);
  /// \brief The hardware lost its state (`why`): aborts a running goal; the arm holds what is
  /// measured once the state is back.
  void suspend(const std::string& why);
  /// \brief Free-drive on: aborts a previewed goal and rejects new ones ("free-drive active"); a
  /// measured arm follows its measured pose. Off: holds the measured pose (or the desired state,
  /// brought to rest) of that instant.
  void setFreeDrive(bool active, const ros::Time& now);
  /// \brief Ends a goal running in simulation as preempted, because `why` commands the arm now.
  void preempt(const std::string& why);
  /// \brief true while a goal runs, awaits its confirmation or executes on the real robot.
  bool active() const { return phase_ != Phase::Idle; }

private:
  enum class Phase { Idle, Simulating, AwaitingConfirmation, Relaying };

  double toTime(const ros::Time& t) const { return (t - origin_).toSec(); }
  void onGoal(GoalHandle gh);
  /// Empty when the goal may be planned now, else the result code and message of its rejection.
  std::pair<int, std::string> admissible(const control_msgs::FollowJointTrajectoryGoal& goal, const ros::Time& start,
                                         const ros::Time& now) const;
  void onCancel(GoalHandle gh);
  bool onConfirm(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res);
  void reject(GoalHandle& gh, int code, const std::string& message);
  void finish(int code, const std::string& message);
  std::vector<double> realArm() const;
  void publishFeedback(const ros::Time& now, const ArmController::Cycle& cycle);

  ArmController& arm_;
  const RobotHardware& hw_;
  Options options_;
  ros::Time origin_;
  std::unique_ptr<RealDriverRelay> relay_;
  const RobotHardware* real_;
  ClockedActionServer<Action> server_;
  ros::ServiceServer confirm_;
  GoalHandle active_;
  Phase phase_ = Phase::Idle;
  ros::Time confirm_deadline_;
  ros::Time last_feedback_;  ///< of the active goal
  double goal_start_ = 0.0;  ///< controller time the active goal's motion starts
  std::string name_;
  bool suspended_ = true;  ///< no state yet, or the states stopped
  bool updated_ = false;   ///< some cycle ran with a state
  bool free_drive_ = false;
};

/// \brief Sets actionlib's parameters of the action `name` (relative to `nh`) before its server is built: no
/// status timer (ClockedActionServer sends the heartbeat), queue sizes `options.queue_size` (actionlib's
/// defaults, server 50 and C++ client 10 goals, drop goals and results of a larger burst, which leaves their
/// clients waiting forever). The client sizes are read from the
/// action's namespace by every roscpp ActionClient of it created afterwards.
ros::NodeHandle actionParameters(ros::NodeHandle& nh, const std::string& name,
                                 const ArmActionServer::Options& options);
}  // namespace vrrw_control
