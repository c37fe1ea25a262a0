#include "bag_instructions.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <stdexcept>
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
}  // namespace vrrw_evaluation
