#pragma once
#include <memory>
#include <string>
#include <vector>
#include <vrrw_control/joint_sample.h>
#include <vrrw_control/robot_hardware.h>
#include <vrrw_control/tolerances.h>
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_control/trajectory_validator.h>

namespace vrrw_control
{
/// \brief Executes validated joint trajectories on a RobotHardware like joint_trajectory_controller:
/// samples the interpolant each cycle, checks path, goal and goal-time tolerances, and brings the
/// arm to rest with bounded deceleration on cancel, preemption or violation.
class ArmController
{
public:
  enum class Outcome { None, Succeeded, PathToleranceViolated, GoalToleranceViolated };

  /// \brief What one control cycle produced.
  struct Cycle
  {
    bool goal_active = false;  ///< a goal is running (or waiting for its start)
    Outcome outcome = Outcome::None;  ///< set once, in the cycle the goal ends
    std::string message;
    JointSample desired, actual, error;
  };

  ArmController(RobotHardware& hardware, const std::vector<std::string>& joints, TrajectoryValidator validator,
                std::vector<double> stop_deceleration);

  /// \brief Where the arm will rest if stopped at `now`: the state a new goal must start from.
  JointSample restState(double now) const;
  /// \brief Runs the validation gate against restState(now).
  Validation validate(const vrrw_trajectory::JointTrajectory& goal, double now) const;
  /// \brief Starts an accepted motion at `start_time`, or after the stop from the current motion.
  void start(const Validation& accepted, double start_time, double now, const Tolerances& tolerances);
  /// \brief Ends the goal and stops with bounded deceleration from the desired state at `now`.
  void stop(double now);

  /// \brief Holds the arm at positions measured elsewhere (the real arm), dropping any motion.
  void adopt(const std::vector<double>& positions);

  /// \brief One control cycle; call between hardware.read() and hardware.write(). The first cycle
  /// holds whatever the hardware commands then (a physics robot's first measured state).
  Cycle update(double time);

  /// \brief True while a goal or a stop runs.
  bool moving() const;
  const std::vector<std::string>& joints() const { return joints_; }
  const TrajectoryValidator& validator() const { return validator_; }

private:
  JointSample desiredAt(double time) const;
  JointSample actual() const;
  void checkTolerances(double t, Cycle& cycle);
  void holdCommand();
  void endGoal(Outcome outcome, const std::string& message, double time, Cycle& cycle);

  RobotHardware& hw_;
  std::vector<std::string> joints_;
  std::vector<int> index_;  ///< joint -> hardware index
  TrajectoryValidator validator_;
  std::vector<double> stop_deceleration_;

  std::unique_ptr<TrajectoryInterpolator> stopping_;  ///< active stop, absolute time base
  std::unique_ptr<TrajectoryInterpolator> motion_;    ///< active goal, times from motion_start_
  double motion_start_ = 0.0;
  Tolerances tolerances_;
  JointSample hold_;  ///< rest state when nothing runs
  bool started_ = false;
};
}  // namespace vrrw_control
