#pragma once
#include <Eigen/Dense>
#include <optional>
#include <vrrw_control/trajectory_interpolator.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_interaction
{
/// \brief A plan played back by the ghost: the arm where the controller will have it (the controller's own
/// spline interpolation, vrrw_control::TrajectoryInterpolator) `t` s after the preview started, then held at
/// the plan's end for kHold s, so the eye sees where it ends before the ghost returns to its pose.
class PlanPreview
{
public:
  static constexpr double kHold = 0.5;  ///< s at the end point

  /// \brief Starts playing `plan` at time `start` (s, any clock the caller keeps using).
  void play(const vrrw_trajectory::JointTrajectory& plan, double start);
  /// \brief Ends the preview (the ghost was moved).
  void stop() { interpolator_.reset(); }
  /// \brief The previewed arm joints at `now`; none without a preview or after its end and hold.
  std::optional<Eigen::VectorXd> at(double now) const;

private:
  std::optional<vrrw_control::TrajectoryInterpolator> interpolator_;
  double start_ = 0.0;
};
}  // namespace vrrw_interaction
