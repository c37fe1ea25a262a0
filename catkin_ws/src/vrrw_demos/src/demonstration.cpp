#include <vrrw_demos/demonstration.h>

#include <algorithm>

namespace vrrw_demos
{
const Pose* objectPoseAt(const Demonstration& demo, const std::string& object, double t)
{
  const auto found = demo.objects.find(object);
  if (found == demo.objects.end() || found->second.empty())
    return nullptr;
  const std::vector<TimedPose>& poses = found->second;
  const auto after = std::upper_bound(poses.begin(), poses.end(), t,
                                      [](double time, const TimedPose& pose) { return time < pose.time; });
  return after == poses.begin() ? &poses.front().pose : &(after - 1)->pose;
}
}  // namespace vrrw_demos
