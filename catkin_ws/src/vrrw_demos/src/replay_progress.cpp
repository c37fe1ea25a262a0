#include <vrrw_demos/replay_progress.h>

#include <algorithm>
#include <cstdio>

namespace vrrw_demos
{
std::string instructionAt(const std::vector<Segment>& instructions, double time)
{
  bool any = false;
  for (const Segment& segment : instructions)
  {
    if (segment.gripper)
      continue;
    any = true;
    if (time >= segment.start && time <= segment.end)
      return segment.name;
  }
  return any ? "rest" : "";
}

std::string progressText(const std::string& name, double elapsed, double duration)
{
  const double done = duration > 0.0 ? std::clamp(elapsed / duration, 0.0, 1.0) : 1.0;
  char text[64];
  std::snprintf(text, sizeof(text), "%.0f %%, %.1f s left", 100.0 * done, std::max(0.0, duration - elapsed));
  return (name.empty() ? "" : name + ", ") + text;
}

std::string progressLine(const ReplayPath& path, const std::vector<Segment>& instructions, double first_state,
                         double t)
{
  return progressText(instructionAt(instructions, first_state + path.recordedTime(t)), t, path.trajectory.duration());
}
}  // namespace vrrw_demos
