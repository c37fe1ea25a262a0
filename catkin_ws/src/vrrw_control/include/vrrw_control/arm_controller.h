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
/// samples the interpolant each cycle, checks path, goal and goal-time tolerances, splices a new
/// motion into the running one (or, strict, stops first), and brings the arm to rest with bounded
/// deceleration on cancel. On measuring hardware a motion that fails its tolerances holds the
/// measured position (joint_trajectory_controller's hold), so the arm never heads on to where the
/// aborted motion wanted it.
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

  struct Options
  {
    /// \brief true: a new motion joins the running one at once (TrajectoryValidator::splice);
    /// false: the strict gate, the running motion stops first and the new one starts from rest.
    bool splice = true;
    std::vector<double> stop_deceleration;  ///< rad/s^2 per joint
  };

  /// \brief A gate verdict with the instant (controller time) the motion joins at.
  struct Plan
  {
    Validation validation;
    double start = 0.0;
  };

  ArmController(RobotHardware& hardware, const std::vector<std::string>& joints, TrajectoryValidator validator,
                Options options);

  /// \brief Runs the gate for a goal whose own time 0 is `start_time`, arriving at `now`.
  Plan plan(const vrrw_trajectory::JointTrajectory& goal, double start_time, double now) const;
  /// \brief Starts an accepted plan; it replaces whatever would run from plan.start on.
  void start(const Plan& accepted, const Tolerances& tolerances, double now);
  /// \brief Ends the goal and stops with bounded deceleration from the desired state at `now`.
  void stop(double now);
  /// \brief Ends the goal and holds the measured positions at rest (physics free-drive, stale state).
  void holdMeasured();
  /// \brief Ends the goal and forgets the state: the next update() holds what the hardware commands
  /// then (a physics robot whose state was lost re-reads it first).
  void release();
  /// \brief While on, a resting arm of measuring hardware follows its measured positions with zero
  /// velocity, so compliant drives feel no pull towards an old target.
  void followMeasured(bool on) { follow_measured_ = on; }

  /// \brief Holds the arm at positions measured elsewhere (the real arm), dropping any motion.
  void adopt(const std::vector<double>& positions);

  /// \brief One control cycle; call between hardware.read() and hardware.write(). The first cycle
  /// holds whatever the hardware commands then (a physics robot's first measured state).
  Cycle update(double time);

  /// \brief True while a goal or a stop runs.
  bool moving() const { return !motions_.empty(); }
  bool splices() const { return options_.splice; }
  const std::vector<std::string>& joints() const { return joints_; }
  const TrajectoryValidator& validator() const { return validator_; }

private:
  /// A motion runs from `start` (controller time) until a later motion starts.
  struct Motion
  {
    std::shared_ptr<const TrajectoryInterpolator> path;
    double start = 0.0;
    double end() const { return start + path->endTime(); }
  };

  JointSample desiredAt(double time) const;
  JointSample actual() const;
  JointSample restState(double now) const;
  /// Drops what would run from `time` on and runs `path` from there.
  void runFrom(double time, vrrw_trajectory::JointTrajectory path);
  void checkTolerances(double t, Cycle& cycle);
  void holdCommand();
  void endGoal(Outcome outcome, const std::string& message, double time, Cycle& cycle);

  RobotHardware& hw_;
  std::vector<std::string> joints_;
  std::vector<int> index_;  ///< joint -> hardware index
  TrajectoryValidator validator_;
  Options options_;

  std::vector<Motion> motions_;  ///< by start time; each runs until the next one starts
  JointSample hold_;             ///< rest state when nothing runs
  bool goal_ = false;            ///< the last motion is a goal (not a stop)
  double goal_start_ = 0.0;
  Tolerances tolerances_;
  bool started_ = false;
  bool follow_measured_ = false;
};
}  // namespace vrrw_control
