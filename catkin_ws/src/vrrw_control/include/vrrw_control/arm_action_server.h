#pragma once
#include <actionlib/server/action_server.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <memory>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <vrrw_control/arm_controller.h>
#include <vrrw_control/real_driver_relay.h>

namespace vrrw_control
{
/// \brief The FollowJointTrajectory action of one arm: gate, preemption, cancel with a smooth stop,
/// feedback every control cycle, results with control_msgs error codes. In real mode a goal first
/// runs in simulation, then waits for `confirm_real_execution` before the relay sends it.
class ArmActionServer
{
public:
  using Action = control_msgs::FollowJointTrajectoryAction;
  using GoalHandle = actionlib::ServerGoalHandle<Action>;

  struct Options
  {
    Tolerances defaults;            ///< used where a goal leaves a tolerance at 0
    ros::Time clock_origin;         ///< maps to controller time 0 (keeps doubles small and exact)
    double confirm_timeout = 120.0;  ///< real mode: s to wait for the confirmation
  };

  /// \brief `relay` non-null selects real mode. `real` (optional, real mode) measures the real arm:
  /// whenever no goal is previewed in simulation the virtual arm adopts its state, so the preview
  /// and the gate start from where the real arm is, also after a relayed goal ended elsewhere.
  ArmActionServer(ros::NodeHandle& nh, ArmController& arm, const RobotHardware& hardware, Options options,
                  std::unique_ptr<RealDriverRelay> relay, const RobotHardware* real = nullptr);

  /// \brief One control cycle at `now`; between hardware read and write.
  void update(const ros::Time& now);

private:
  enum class Phase { Idle, Simulating, AwaitingConfirmation, Relaying };

  double toTime(const ros::Time& t) const { return (t - origin_).toSec(); }
  void onGoal(GoalHandle gh);
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
  actionlib::ActionServer<Action> server_;
  ros::ServiceServer confirm_;
  GoalHandle active_;
  Phase phase_ = Phase::Idle;
  ros::Time confirm_deadline_;
  std::string name_;
};
}  // namespace vrrw_control
