#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vrrw_control/splice_segment.h>

namespace vrrw_control
{
namespace
{
std::string exceeds(const char* what, double value, const char* limit, double bound)
{
  std::ostringstream s;
  s.precision(6);
  s << what << " " << value << " exceeds " << limit << " " << bound;
  return s.str();
}

/// A hair of slack so that a duration found by the search passes the same check again.
constexpr double kRounding = 1e-9;
}  // namespace

SpliceCheck checkSplice(SplineSegment::Order order, const JointSample& from, const JointSample& to,
                        double duration, const std::vector<JointLimits>& limits, double share)
{
  for (size_t j = 0; j < limits.size(); ++j)
  {
    const JointLimits& l = limits[j];
    const double max_velocity = std::max(share * l.max_velocity, std::abs(from.velocities[j]));
    const double max_acceleration = order == SplineSegment::Order::Quintic ?
                                        std::max(share * l.max_acceleration, std::abs(from.accelerations[j])) :
                                        share * l.max_acceleration;
    const SplineSegment segment(order, duration, from.positions[j], from.velocities[j],
                                from.accelerations[j], to.positions[j], to.velocities[j], to.accelerations[j]);
    for (int k = 0; k <= kSpliceSamples; ++k)
    {
      double q, v, a;
      segment.sample(duration * k / kSpliceSamples, q, v, a);
      if (l.has_position_limits && (q < l.min_position - kRounding || q > l.max_position + kRounding))
        return { l.name, exceeds("position", q, "the limit", q < l.min_position ? l.min_position : l.max_position) };
      if (std::abs(v) > max_velocity * (1.0 + kRounding))
        return { l.name, exceeds("velocity", v, "the limit", l.max_velocity) };
      if (std::abs(a) > max_acceleration * (1.0 + kRounding))
        return { l.name, exceeds("acceleration", a, "the limit", l.max_acceleration) };
    }
  }
  return {};
}

double shortestSplice(SplineSegment::Order order, const JointSample& from, const JointSample& to, double at_least,
                      const std::vector<JointLimits>& limits)
{
  double low = std::max(at_least, kShortestSplice);
  if (checkSplice(order, from, to, low, limits, kSpliceShare).ok())
    return low;
  double high = 2.0 * low;
  while (!checkSplice(order, from, to, high, limits, kSpliceShare).ok())
  {
    low = high;
    high *= 2.0;
    if (high > kLongestSplice)
      return std::numeric_limits<double>::infinity();
  }
  // feasible durations form an interval above the shortest one: bisect between the last
  // infeasible and the first feasible duration
  while (high - low > 0.01 * high)
  {
    const double middle = 0.5 * (low + high);
    (checkSplice(order, from, to, middle, limits, kSpliceShare).ok() ? high : low) = middle;
  }
  return high;
}
}  // namespace vrrw_control
