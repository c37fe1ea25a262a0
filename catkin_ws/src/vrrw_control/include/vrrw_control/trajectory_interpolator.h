#pragma once
#include <vector>
#include <vrrw_control/joint_sample.h>
#include <vrrw_control/spline_segment.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_control
{
/// \brief Piecewise spline through the points of a trajectory; holds the first point before its
/// time and the last point after it, with zero velocity and acceleration.
class TrajectoryInterpolator
{
public:
  explicit TrajectoryInterpolator(const vrrw_trajectory::JointTrajectory& trajectory);

  /// \brief The state at time t (seconds, same clock as the point times).
  JointSample sample(double t) const;
  /// \brief Index of the last point whose time is <= t (0 before the first point).
  size_t segmentAt(double t) const;

  double startTime() const { return times_.front(); }
  double endTime() const { return times_.back(); }
  size_t jointCount() const { return joints_; }
  const vrrw_trajectory::JointTrajectory& trajectory() const { return trajectory_; }

private:
  vrrw_trajectory::JointTrajectory trajectory_;
  size_t joints_ = 0;
  std::vector<double> times_;
  std::vector<std::vector<SplineSegment>> segments_;  ///< [segment][joint]
};
}  // namespace vrrw_control
