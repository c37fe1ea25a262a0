#pragma once
#include <string>
#include <vector>

#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_demos
{
/// \brief How slowly a replay moves the arm to the recorded start.
struct ApproachOptions
{
  /// The joint that moves farthest averages this fraction of its velocity limit; the controller's cubic
  /// between two rests peaks at 1.5 times the average, so 0.2 keeps every joint below 0.3 of its limit.
  double velocity_fraction = 0.2;
  double min_duration = 0.5;  ///< s: even a move of nothing takes this long (the controller needs a motion)
};

/// \brief From \a from to \a to, at rest at both ends: two points, the second after the longest
/// |to - from| / (velocity_fraction * max_velocity) over the joints (at least min_duration).
/// Throws DemoError when the sizes differ or a velocity limit is not positive.
vrrw_trajectory::JointTrajectory approachMove(const std::vector<std::string>& joints, const std::vector<double>& from,
                                              const std::vector<double>& to, const std::vector<double>& max_velocity,
                                              const ApproachOptions& options = {});
}  // namespace vrrw_demos
