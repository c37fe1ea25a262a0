#include <vrrw_dmp/dmp_parameters.h>

#include <cmath>
#include <cstdio>

#include <vrrw_dmp/dmp_error.h>

#include "format_number.h"

namespace vrrw_dmp
{
std::string toString(AmplitudeScaling scaling)
{
  switch (scaling)
  {
    case AmplitudeScaling::goal_offset:
      return "goal";
    case AmplitudeScaling::demo_amplitude:
      return "amplitude";
    case AmplitudeScaling::automatic:
      return "auto";
  }
  return "goal";
}

AmplitudeScaling amplitudeScalingFromString(const std::string& text)
{
  if (text == "goal")
    return AmplitudeScaling::goal_offset;
  if (text == "amplitude")
    return AmplitudeScaling::demo_amplitude;
  if (text == "auto")
    return AmplitudeScaling::automatic;
  throw DmpError("scaling '" + text + "': expected goal, amplitude or auto");
}

double DmpParameters::damping() const
{
  return D ? *D : 2.0 * std::sqrt(K);
}

void DmpParameters::validate() const
{
  if (basis_count == 0)
    throw DmpError("basis count N = 0: need at least one basis function");
  if (basis_count > kMaxBasisCount)
    throw DmpError("basis count N = " + std::to_string(basis_count) + ": more than the limit of " +
                   std::to_string(kMaxBasisCount));
  if (!(alpha > 0.0) || !std::isfinite(alpha))
    throw DmpError("alpha = " + format(alpha) + ": must be a finite number > 0");
  if (!(K > 0.0) || !std::isfinite(K))
    throw DmpError("K = " + format(K) + ": must be a finite number > 0");
  if (D && (!(*D >= 0.0) || !std::isfinite(*D)))
    throw DmpError("D = " + format(*D) + ": must be a finite number >= 0");
  if (!(degenerate_ratio >= 0.0) || !std::isfinite(degenerate_ratio))
    throw DmpError("degenerate ratio = " + format(degenerate_ratio) + ": must be >= 0");
  if (!(still_range >= 0.0) || !std::isfinite(still_range))
    throw DmpError("still range = " + format(still_range) + ": must be >= 0");
  if (derivative_half_window == 0)
    throw DmpError("derivative half window = 0: must be >= 1");
}
}  // namespace vrrw_dmp
