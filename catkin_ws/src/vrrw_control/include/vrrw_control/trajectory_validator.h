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
  /// at the current state (prepended at t = 0 when the first point lies later, or a blend).
  vrrw_trajectory::JointTrajectory executable;
  bool blended = false;

  bool ok() const { return error == Error::None; }
};

/// \brief Options of the gate.
struct ValidationOptions
{
  double start_tolerance = 0.01;  ///< rad (m) between the first point and the current state
  bool insert_blend = false;      ///< blend from the current state instead of rejecting
  double blend_margin = 1.5;      ///< blend duration = margin x the fastest limit-respecting cubic
  double interpolant_slack = 0.1;  ///< interpolated velocity may exceed the limit by this fraction
  int samples_per_segment = 16;
};

/// \brief The gate every goal passes before any joint moves: joint names, sizes, finite values,
/// strictly increasing times, position/velocity/acceleration limits at the points, position and
/// velocity limits of the interpolant between them, and the start state.
class TrajectoryValidator
{
public:
  TrajectoryValidator(std::vector<JointLimits> limits, ValidationOptions options);

  /// \brief Checks a goal (any joint order, times from its start) against the current robot state.
  Validation validate(const vrrw_trajectory::JointTrajectory& goal, const JointSample& current) const;

  const std::vector<JointLimits>& limits() const { return limits_; }
  const ValidationOptions& options() const { return options_; }

private:
  bool checkJoints(const vrrw_trajectory::JointTrajectory& goal, Validation& v, std::vector<size_t>& order) const;
  bool checkPoints(const vrrw_trajectory::JointTrajectory& goal, const std::vector<size_t>& order, Validation& v) const;
  bool checkInterpolant(int first_goal_point, Validation& v) const;
  double blendDuration(const JointSample& from, const vrrw_trajectory::TrajectoryPoint& to) const;

  std::vector<JointLimits> limits_;
  ValidationOptions options_;
};
}  // namespace vrrw_control
