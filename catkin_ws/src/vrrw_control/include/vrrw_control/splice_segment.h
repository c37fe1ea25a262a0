#pragma once
#include <string>
#include <vector>
#include <vrrw_control/joint_limits.h>
#include <vrrw_control/joint_sample.h>
#include <vrrw_control/spline_segment.h>

namespace vrrw_control
{
/// \brief The first limit a splice segment breaks: empty reason when it keeps every limit.
struct SpliceCheck
{
  std::string joint;
  std::string reason;
  bool ok() const { return reason.empty(); }
};

/// The segment by which a new motion joins the arm's current one runs from the current desired state
/// to the first point the new motion keeps: a quintic (position, velocity and acceleration continuous
/// at the splice) when that point carries accelerations, a cubic (position and velocity continuous,
/// as joint_trajectory_controller joins a cubic trajectory) when it carries velocities only.

/// \brief Checks the segment of `order` from `from` to `to` over `duration` (s) at kSpliceSamples
/// instants against position limits, |velocity| <= `share` x max_velocity and |acceleration| <= `share`
/// x max_acceleration; a start state already beyond a bound (a motion at its limit) raises it to the start's value.
SpliceCheck checkSplice(SplineSegment::Order order, const JointSample& from, const JointSample& to,
                        double duration, const std::vector<JointLimits>& limits, double share = 1.0);

/// \brief The shortest duration >= `at_least` (to 1 %) over which that segment keeps kSpliceShare of
/// every limit (so that the peaks between the samples stay inside): the time-optimal blend of this shape. Infinity when no duration up to kLongestSplice does (e.g. the
/// overshoot of a fast arm would leave its position limits).
double shortestSplice(SplineSegment::Order order, const JointSample& from, const JointSample& to, double at_least,
                      const std::vector<JointLimits>& limits);

constexpr int kSpliceSamples = 64;
constexpr double kSpliceShare = 0.995;
/// \brief Seconds; a splice segment is never shorter (a target at the current state still gets a segment).
constexpr double kShortestSplice = 1e-3;
constexpr double kLongestSplice = 600.0;
}  // namespace vrrw_control
