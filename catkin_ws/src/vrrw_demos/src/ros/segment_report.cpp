#include "segment_report.h"

#include <cstdio>
#include <memory>
#include <sstream>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/tcp_kinematics.h>
#include <yaml-cpp/yaml.h>

namespace vrrw_demos
{
namespace
{
/// The TCP pose (x y z qx qy qz qw, world frame) of a state; empty without a URDF or TCP link.
class TcpPoses
{
public:
  TcpPoses(const Demonstration& demo, const RobotTrack& track)
  {
    try
    {
      kinematics_ = std::make_unique<TcpKinematics>(demo, track);
    }
    catch (const DemoError&)
    {
      kinematics_.reset();  // the table and YAML go without poses
    }
  }

  std::vector<double> at(const RobotState& state) const
  {
    if (!kinematics_)
      return {};
    const Eigen::Isometry3d pose = kinematics_->at(state);
    const Eigen::Quaterniond rotation(pose.rotation());
    return { pose.translation().x(), pose.translation().y(), pose.translation().z(),
             rotation.x(), rotation.y(), rotation.z(), rotation.w() };
  }

private:
  std::unique_ptr<TcpKinematics> kinematics_;
};

std::string fixed(double value, int digits)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, value);
  return buffer;
}
}  // namespace

SegmentReport segmentReport(const std::string& bag, const Demonstration& demo,
                            const SegmentationOptions& options)
{
  YAML::Emitter out;
  std::ostringstream table;
  out << YAML::BeginMap << YAML::Key << "bag" << YAML::Value << bag;
  out << YAML::Key << "start_stamp" << YAML::Value << YAML::Precision(19) << demo.start_stamp
      << YAML::Comment("s since the epoch; segment times are seconds after it");
  out << YAML::Key << "thresholds" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "still_speed" << YAML::Value << options.still_speed;
  out << YAML::Key << "rest_speed" << YAML::Value << options.rest_speed;
  out << YAML::Key << "min_still" << YAML::Value << options.min_still;
  out << YAML::Key << "gripper_speed" << YAML::Value << options.gripper_speed << YAML::EndMap;
  out << YAML::Key << "robots" << YAML::Value << YAML::BeginMap;
  for (const RobotTrack& track : demo.robots)
  {
    const Segmentation segmentation = segmentPickPlace(track, demo, options);
    const TcpPoses tcp(demo, track);
    out << YAML::Key << track.robot << YAML::Value << YAML::BeginMap << YAML::Key << "segments" << YAML::Value
        << YAML::BeginSeq;
    table << "robot " << track.robot << "\n  instruction          start      end  object     tcp at end (x y z, m)\n";
    for (const Segment& segment : segmentation.segments)
    {
      const auto start_pose = tcp.at(stateAt(track, segment.start));
      const auto end_pose = tcp.at(stateAt(track, segment.end));
      out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << segment.name;
      out << YAML::Key << "kind" << YAML::Value << (segment.gripper ? "gripper" : "arm");
      out << YAML::Key << "start" << YAML::Value << segment.start << YAML::Key << "end" << YAML::Value << segment.end;
      out << YAML::Key << "object" << YAML::Value << segment.object;
      if (segment.gripper)
        out << YAML::Key << "gripper_target" << YAML::Value << segment.gripper_target;
      if (!start_pose.empty())
        out << YAML::Key << "tcp_start" << YAML::Value << YAML::Flow << start_pose << YAML::Key << "tcp_end"
            << YAML::Value << YAML::Flow << end_pose;
      out << YAML::EndMap;
      char line[160];
      std::snprintf(line, sizeof(line), "  %-18s %7.3f  %7.3f  %-10s", segment.name.c_str(), segment.start,
                    segment.end, segment.object.empty() ? "-" : segment.object.c_str());
      table << line;
      if (!end_pose.empty())
        table << " " << fixed(end_pose[0], 3) << " " << fixed(end_pose[1], 3) << " " << fixed(end_pose[2], 3);
      table << "\n";
    }
    out << YAML::EndSeq << YAML::Key << "warnings" << YAML::Value << YAML::BeginSeq;
    for (const std::string& warning : segmentation.warnings)
    {
      out << warning;
      table << "  warning: " << warning << "\n";
    }
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndMap << YAML::EndMap;
  return { std::string(out.c_str()) + "\n", table.str() };
}

}  // namespace vrrw_demos
