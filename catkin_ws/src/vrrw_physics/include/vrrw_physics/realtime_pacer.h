#pragma once
#include <chrono>

namespace vrrw_physics
{
/// \brief Keeps simulated time in step with the wall clock: after each step, how long to wait.
///
/// A step that falls behind by more than `max_lag` starts a new reference instead of racing to catch up
/// (a paused debugger or a loaded machine must not be followed by a burst of fast steps).
class RealtimePacer
{
public:
  using Clock = std::chrono::steady_clock;

  explicit RealtimePacer(double max_lag = 0.1) : max_lag_(max_lag) {}

  /// \brief Starts pacing from simulated time `sim_time` now (after a pause, too).
  void restart(double sim_time, Clock::time_point now = Clock::now());
  /// \brief Seconds to sleep before the step that follows `sim_time` (0 when late).
  double wait(double sim_time, Clock::time_point now = Clock::now());

private:
  double max_lag_;
  Clock::time_point start_ = Clock::now();
  double started_at_ = 0.0;
};
}  // namespace vrrw_physics
