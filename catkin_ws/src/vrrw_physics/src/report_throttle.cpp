#include <vrrw_physics/report_throttle.h>

#include <cctype>

namespace vrrw_physics
{
namespace
{
/// The message with every number made '#': what stays the same while a cause repeats.
std::string shape(const std::string& message)
{
  std::string out;
  for (char c : message)
    if (std::isdigit(static_cast<unsigned char>(c)))
    {
      if (out.empty() || out.back() != '#')
        out += '#';
    }
    else
      out += c;
  return out;
}
}  // namespace

std::string ReportThrottle::admit(const std::string& source, const std::string& message, double now)
{
  Kind& kind = kinds_[source + '\n' + shape(message)];
  if (kind.seen && now - kind.last < period_ && now >= kind.last)
  {
    ++kind.held;
    return "";
  }
  const std::string line =
      kind.held > 0 ? message + " (" + std::to_string(kind.held) + " more like it held back)" : message;
  kind = { now, 0, true };
  return line;
}
}  // namespace vrrw_physics
