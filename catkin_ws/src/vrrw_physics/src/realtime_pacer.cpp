#include <vrrw_physics/realtime_pacer.h>

namespace vrrw_physics
{
void RealtimePacer::restart(double sim_time, Clock::time_point now)
{
  start_ = now;
  started_at_ = sim_time;
}

double RealtimePacer::wait(double sim_time, Clock::time_point now)
{
  const double ahead = (sim_time - started_at_) - std::chrono::duration<double>(now - start_).count();
  if (ahead < -max_lag_)
    restart(sim_time, now);
  return ahead > 0.0 ? ahead : 0.0;
}
}  // namespace vrrw_physics
