#include <vrrw_physics/realtime_pacer.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace vrrw_physics
{
void RealtimePacer::restart(double sim_time, Clock::time_point now)
{
  start_ = now;
  started_at_ = sim_time;
}

double RealtimePacer::wait(double sim_time, Clock::time_point now)
{
  if (std::isinf(rtf_))
    return 0.0;
  const double ahead = (sim_time - started_at_) / rtf_ - std::chrono::duration<double>(now - start_).count();
  if (ahead < -max_lag_)
    restart(sim_time, now);
  return ahead >= min_wait_ && ahead > 0.0 ? ahead : 0.0;
}

double parseRealTimeFactor(const std::string& text, const std::string& what)
{
  if (text == "max")
    return std::numeric_limits<double>::infinity();
  std::size_t used = 0;
  double rtf = std::numeric_limits<double>::quiet_NaN();
  try
  {
    rtf = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(rtf > 0.0) || !std::isfinite(rtf))
    throw std::invalid_argument(what + ": '" + text + "' is not max or a positive number (the real-time factor)");
  return rtf;
}
}  // namespace vrrw_physics
