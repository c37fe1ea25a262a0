#include <vrrw_demos/tracking_error.h>

#include <algorithm>
#include <cmath>

namespace vrrw_demos
{
TrackingError trackingError(const std::vector<MeasuredState>& measured,
                            const std::function<std::vector<double>(double)>& expected, double duration)
{
  TrackingError out;
  double sum = 0.0;
  for (const MeasuredState& state : measured)
  {
    if (state.time < 0.0 || state.time > duration)
      continue;
    ++out.states;
    const std::vector<double> want = expected(state.time);
    for (std::size_t j = 0; j < state.positions.size() && j < want.size(); ++j)
    {
      if (std::isnan(state.positions[j]))
        continue;
      const double e = state.positions[j] - want[j];
      out.max = std::max(out.max, std::abs(e));
      sum += e * e;
      ++out.values;
    }
  }
  out.rms = out.values ? std::sqrt(sum / static_cast<double>(out.values)) : 0.0;
  return out;
}
}  // namespace vrrw_demos
