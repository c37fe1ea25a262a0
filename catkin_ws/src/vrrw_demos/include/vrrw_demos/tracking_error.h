#pragma once
#include <cstddef>
#include <functional>
#include <vector>

namespace vrrw_demos
{
/// \brief A measured state of the arm: time on the replayed path's clock (s from its start) and the
/// positions in the path's joint order (NaN where the message lacked the joint).
struct MeasuredState
{
  double time = 0.0;
  std::vector<double> positions;
};

/// \brief How closely the arm followed a path: over every joint value measured during the motion.
struct TrackingError
{
  double max = 0.0;         ///< rad (m): the largest |measured - expected|
  double rms = 0.0;         ///< rad (m): root mean square over all values
  std::size_t states = 0;   ///< measured states within the motion
  std::size_t values = 0;   ///< joint values compared (states x joints, less the missing ones)
};

/// \brief The error of every measured state with 0 <= time <= duration against \a expected(time) (the
/// positions the controller commanded then, in the same joint order); states outside are not counted.
TrackingError trackingError(const std::vector<MeasuredState>& measured,
                            const std::function<std::vector<double>(double)>& expected, double duration);
}  // namespace vrrw_demos
