#include <algorithm>
#include <vrrw_control/control_error.h>
#include <vrrw_control/trajectory_interpolator.h>

namespace vrrw_control
{
namespace
{
SplineSegment::Order orderOf(const vrrw_trajectory::TrajectoryPoint& a, const vrrw_trajectory::TrajectoryPoint& b)
{
  const size_t n = a.positions.size();
  if (a.velocities.size() == n && b.velocities.size() == n)
  {
    if (a.accelerations.size() == n && b.accelerations.size() == n)
      return SplineSegment::Order::Quintic;
    return SplineSegment::Order::Cubic;
  }
  return SplineSegment::Order::Linear;
}

double at(const std::vector<double>& values, size_t j) { return j < values.size() ? values[j] : 0.0; }
}  // namespace

TrajectoryInterpolator::TrajectoryInterpolator(const vrrw_trajectory::JointTrajectory& trajectory)
  : trajectory_(trajectory)
{
  if (trajectory_.points.empty())
    throw ControlError("trajectory has no points");
  joints_ = trajectory_.points.front().positions.size();
  for (const auto& p : trajectory_.points)
    times_.push_back(p.time);
  for (size_t i = 0; i + 1 < trajectory_.points.size(); ++i)
  {
    const auto& a = trajectory_.points[i];
    const auto& b = trajectory_.points[i + 1];
    const auto order = orderOf(a, b);
    std::vector<SplineSegment> joints;
    for (size_t j = 0; j < joints_; ++j)
      joints.emplace_back(order, b.time - a.time, a.positions[j], at(a.velocities, j), at(a.accelerations, j),
                          b.positions[j], at(b.velocities, j), at(b.accelerations, j));
    segments_.push_back(std::move(joints));
  }
}

size_t TrajectoryInterpolator::segmentAt(double t) const
{
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  return it == times_.begin() ? 0 : static_cast<size_t>(it - times_.begin()) - 1;
}

JointSample TrajectoryInterpolator::sample(double t) const
{
  JointSample s(joints_);
  if (t < times_.front() || t >= times_.back())
  {
    const auto& p = t < times_.front() ? trajectory_.points.front() : trajectory_.points.back();
    s.positions = p.positions;
    return s;
  }
  const size_t i = segmentAt(t);
  for (size_t j = 0; j < joints_; ++j)
    segments_[i][j].sample(t - times_[i], s.positions[j], s.velocities[j], s.accelerations[j]);
  return s;
}
}  // namespace vrrw_control
