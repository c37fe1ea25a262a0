#include "demo_source.h"

#include <cstdio>

#include <vrrw_demos/demo_csv.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/ros/demo_bag.h>
#include <vrrw_demos/segmentation.h>
#include <vrrw_trajectory/csv.h>

namespace vrrw_dmp
{
namespace
{
std::string seconds(double start, double end)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.3f-%.3f s", start, end);
  return text;
}
}  // namespace

DemoSource csvSource(const std::string& path)
{
  DemoSource source;
  source.trajectory = vrrw_trajectory::readCsv(path);
  source.source = path;
  vrrw_trajectory::JointTrajectory with_velocities = source.trajectory;
  for (std::size_t k = 0; k < with_velocities.points.size(); ++k)
    if (with_velocities.points[k].velocities.size() != with_velocities.points[k].positions.size())
      return source;  // no velocities: no motion count, no advice about rests
  source.motions = vrrw_demos::armMotions(vrrw_demos::fromTrajectory(with_velocities, "csv", path),
                                          vrrw_demos::SegmentationOptions{});
  return source;
}

DemoSource bagSource(const std::string& bag, const std::string& robot, const std::string& segment)
{
  const vrrw_demos::Demonstration demo =
      vrrw_demos::readDemonstration(bag, robot.empty() ? std::vector<std::string>{} : std::vector<std::string>{ robot });
  if (demo.robots.size() > 1)
  {
    std::string names;
    for (const auto& track : demo.robots)
      names += (names.empty() ? "" : ", ") + track.robot;
    throw vrrw_demos::DemoError(bag + ": " + std::to_string(demo.robots.size()) + " robots (" + names +
                                "): choose one with --robot");
  }
  vrrw_demos::RobotTrack track = demo.robots.front();
  DemoSource source;
  source.from_bag = true;
  source.source = bag + " robot " + track.robot;
  const vrrw_demos::Segmentation segmentation = vrrw_demos::segmentPickPlace(track, demo);
  for (const auto& found : segmentation.segments)
    source.segments.push_back(found.name);
  if (!segment.empty())
  {
    const vrrw_demos::Segment chosen = vrrw_demos::findSegment(demo, track, segment);
    if (chosen.gripper)
      throw vrrw_demos::DemoError(bag + ": robot '" + track.robot + "': '" + segment +
                                  "' is a gripper action, not an arm motion");
    track = vrrw_demos::slice(track, chosen.start, chosen.end);
    source.source += " segment " + segment + " " + seconds(chosen.start, chosen.end);
  }
  source.motions = vrrw_demos::armMotions(track, vrrw_demos::SegmentationOptions{});
  source.trajectory = vrrw_demos::toTrajectory(track);
  source.trajectory.extra_names.clear();
  source.trajectory.extras.clear();
  return source;
}
}  // namespace vrrw_dmp
