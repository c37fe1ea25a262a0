#pragma once
#include <chrono>
#include <string>

namespace vrrw_physics
{
/// \brief Keeps simulated time at a real-time factor of the wall clock: after each step, how long to wait.
///
/// rtf 1 paces at real time (a person in the loop), rtf N runs N simulated seconds per wall second, an
/// infinite rtf ("max") never waits. A step that falls behind by more than `max_lag` (wall seconds) starts a
/// new reference instead of racing to catch up (a paused debugger or a loaded machine must not be followed by
/// a burst of fast steps). A wait shorter than `min_wait` (wall seconds) is skipped: the steps then come in
/// bursts of about that much time, each followed by one wait, instead of one wake-up per step.
class RealtimePacer
{
public:
  using Clock = std::chrono::steady_clock;

  explicit RealtimePacer(double max_lag = 0.1, double rtf = 1.0, double min_wait = 0.0)
    : max_lag_(max_lag), rtf_(rtf), min_wait_(min_wait)
  {
  }

  /// \brief Starts pacing from simulated time `sim_time` now (after a pause, too).
  void restart(double sim_time, Clock::time_point now = Clock::now());
  /// \brief Wall seconds to wait before the step that follows `sim_time` (0 when late, or ahead by less than
  /// min_wait).
  double wait(double sim_time, Clock::time_point now = Clock::now());
  double rtf() const { return rtf_; }
  /// \brief Paces at \a rtf from the next restart().
  void setRtf(double rtf) { rtf_ = rtf; }

private:
  double max_lag_;
  double rtf_;
  double min_wait_;
  Clock::time_point start_ = Clock::now();
  double started_at_ = 0.0;
};

/// \brief A real-time factor from text: "max" (infinity) or a positive finite number. Throws
/// std::invalid_argument "<what>: '<text>' is not max or a positive number".
double parseRealTimeFactor(const std::string& text, const std::string& what);
}  // namespace vrrw_physics
