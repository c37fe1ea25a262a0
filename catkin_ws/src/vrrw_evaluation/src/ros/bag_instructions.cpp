#include "bag_instructions.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <algorithm>
#include <control_msgs/GripperCommandActionGoal.h>
#include <sensor_msgs/JointState.h>
#include <stdexcept>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_msgs/Event.h>

namespace vrrw_evaluation
{
std::vector<Segment> bagInstructions(const std::string& bag, double start_stamp)
{
  std::vector<Segment> segments;
  bool open = false;
  try
  {
    rosbag::Bag reader(bag, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& m : rosbag::View(reader, rosbag::TopicQuery("/demos/events")))
    {
      const vrrw_msgs::Event::ConstPtr event = m.instantiate<vrrw_msgs::Event>();
      if (!event)
        continue;
      std::string kind = event->kind, name = event->detail;
      if (kind == "annotate")  // vrrw_demos' recorder: "<kind> <name>"
      {
        const auto space = name.find(' ');
        kind = name.substr(0, space);
        name = space == std::string::npos ? "" : name.substr(space + 1);
      }
      const double t = event->header.stamp.toSec() - start_stamp;
      if (kind == "instruction_start")
      {
        if (open)
          throw std::runtime_error(bag + ": /demos/events: " + segments.back().name + " has no end before " + name);
        segments.push_back({ name, t, t });
        open = true;
      }
      else if (kind == "instruction_end" || kind == "instruction_failed")
      {
        if (!open || segments.back().name != name)
          throw std::runtime_error(bag + ": /demos/events: the end of " + name + " without its start");
        segments.back().end = t;
        open = false;
      }
    }
  }
  catch (const rosbag::BagException& e)
  {
    throw std::runtime_error(bag + ": " + e.what());
  }
  if (open)
    throw std::runtime_error(bag + ": /demos/events: " + segments.back().name + " has no end");
  return segments;
}

BagTrack bagTrack(const std::string& bag, const std::string& robot, const std::vector<std::string>& arm_joints,
                  double start_stamp)
{
  BagTrack track;
  track.arm.joint_names = arm_joints;
  const std::string states = "/" + robot + "/joint_states", gripper = "/" + robot + "/gripper_controller/gripper_cmd/goal";
  try
  {
    rosbag::Bag reader(bag, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& m : rosbag::View(reader, rosbag::TopicQuery(std::vector<std::string>{ states, gripper })))
    {
      if (const auto goal = m.instantiate<control_msgs::GripperCommandActionGoal>())
      {
        track.gripper_goals.emplace_back(goal->goal.command.position, goal->goal.command.max_effort);
        continue;
      }
      const auto msg = m.instantiate<sensor_msgs::JointState>();
      if (!msg)
        continue;
      vrrw_trajectory::TrajectoryPoint point;
      point.time = msg->header.stamp.toSec() - start_stamp;
      const auto positions = vrrw_common::findValues(msg->name, msg->position, arm_joints);
      if (positions && (track.arm.points.empty() || point.time > track.arm.points.back().time))
      {
        point.positions = *positions;
        track.arm.points.push_back(point);
      }
    }
  }
  catch (const rosbag::BagException& e)
  {
    throw std::runtime_error(bag + ": " + e.what());
  }
  if (track.arm.points.size() < 2)
    throw std::runtime_error(bag + ": " + states + ": no recorded states of " + robot + "'s arm");
  return track;
}
}  // namespace vrrw_evaluation
