#pragma once
#include <map>
#include <string>

namespace vrrw_physics
{
/// \brief Keeps error reports readable when a cause repeats at the step or message rate: per source (a topic,
/// a service, "world") and kind of message (its text with the numbers left out), the first report passes, then
/// at most one per `period` s, which says how many were held back.
class ReportThrottle
{
public:
  explicit ReportThrottle(double period = 1.0) : period_(period) {}

  /// \brief The line to publish for `message` from `source` at time `now` (s), or "" to hold it back.
  std::string admit(const std::string& source, const std::string& message, double now);

private:
  struct Kind
  {
    double last = 0.0;
    int held = 0;
    bool seen = false;
  };
  double period_;
  std::map<std::string, Kind> kinds_;
};
}  // namespace vrrw_physics
