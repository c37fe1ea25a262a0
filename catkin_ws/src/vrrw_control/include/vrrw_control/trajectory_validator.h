#pragma once
#include <string>
#include <vector>
#include <vrrw_control/joint_limits.h>
#include <vrrw_control/joint_sample.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_control
{
/// \brief Verdict of the validation gate; on rejection names the first offending point, joint and reason.
struct Validation
{
  enum class Error { None, InvalidJoints, InvalidGoal };
  Error error = Error::None;
  std::string message;  ///< one line: "point 3: joint ur5e_elbow_joint: velocity 4.1 exceeds limit 3.14"
  int point = -1;       ///< index in the goal, -1 when the goal as a whole is wrong
  std::string joint;
  /// \brief The accepted motion in robot joint order, times from the motion start; it begins
  /// at the current state (prepended at t = 0 when the first point lies later, or the splice point).
  vrrw_trajectory::JointTrajectory executable;
  bool blended = false;  ///< the goal's times were stretched so that it joins within the limits

  bool ok() const { return error == Error::None; }
};

/// \brief Options of the gate.
struct ValidationOptions
{
  double start_tolerance = 0.01;   ///< rad (m) between the first point and the current state (strict gate)
  double interpolant_slack = 0.1;  ///< interpolated velocity may exceed the limit by this fraction
  int samples_per_segment = 16;
};

/// \brief The gate every goal passes before any joint moves: joint names, sizes, finite values,
/// strictly increasing times, position/velocity/acceleration limits at the points, position and
/// velocity limits of the interpolant between them, and how the goal joins the arm's motion.
///
/// Two ways to join. validate(): the strict gate of real mode, the goal must start at the resting
/// arm (start tolerance). splice(): as joint_trajectory_controller, the goal joins the arm's motion at
/// the current instant; points whose time has passed are dropped and a spline (splice_segment.h) runs
/// from the current desired position, velocity and acceleration to the first point kept, stretched to
/// the shortest duration that keeps the limits when the goal's own timing would break them (a goal that
/// starts where the resting arm is keeps its own first segment's timing, checked like its others).
class TrajectoryValidator
{
public:
  TrajectoryValidator(std::vector<JointLimits> limits, ValidationOptions options);

  /// \brief Checks a goal (any joint order, times from its start) against the resting robot state.
  Validation validate(const vrrw_trajectory::JointTrajectory& goal, const JointSample& current) const;

  /// \brief Checks a goal that joins the motion whose desired state at the splice instant is `current`
  /// (velocities and accelerations included); `elapsed` s of the goal's own time have passed by then
  /// (its header stamp lies in the past). Points at or before `elapsed` are dropped, except: the
  /// last point is always kept, and at rest a first point farther than the start tolerance is kept
  /// and blended to (the goal expects the arm there). Never rejects for the start tolerance.
  Validation splice(const vrrw_trajectory::JointTrajectory& goal, const JointSample& current,
                    double elapsed = 0.0) const;

  const std::vector<JointLimits>& limits() const { return limits_; }
  const ValidationOptions& options() const { return options_; }

private:
  bool checkJoints(const vrrw_trajectory::JointTrajectory& goal, Validation& v, std::vector<size_t>& order) const;
  bool checkPoints(const vrrw_trajectory::JointTrajectory& goal, const std::vector<size_t>& order, Validation& v) const;
  /// Joint names and points checked and reordered into robot order (into v.executable).
  bool checkAndReorder(const vrrw_trajectory::JointTrajectory& goal, Validation& v) const;
  /// `index_shift`: index in v.executable minus index in the goal.
  bool checkInterpolant(int index_shift, Validation& v) const;
  /// `own_segment`: the splice replaces the goal's own first segment (it starts where the resting arm is).
  size_t firstKeptPoint(const std::vector<vrrw_trajectory::TrajectoryPoint>& points, const JointSample& current,
                        double elapsed, bool& own_segment) const;

  std::vector<JointLimits> limits_;
  ValidationOptions options_;
};
}  // namespace vrrw_control
