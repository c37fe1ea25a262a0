#include <vrrw_evaluation/annotations.h>
#include <vrrw_evaluation/evaluation_error.h>


#include <vrrw_evaluation/pick_place_task.h>

namespace vrrw_evaluation
{
std::vector<vrrw_demos::Segment> annotatedInstructions(const vrrw_demos::Demonstration& demo)
{
  std::vector<vrrw_demos::Segment> segments;
  bool open = false;
  const std::string where = demo.source + ": /demos/events: ";
  for (const vrrw_demos::DemoEvent& event : demo.events)
  {
    std::string kind = event.kind, name = event.detail;
    if (kind == "annotate")  // vrrw_demos' recorder: "<kind> <name>"
    {
      const auto space = name.find(' ');
      kind = name.substr(0, space);
      name = space == std::string::npos ? "" : name.substr(space + 1);
    }
    if (kind == "instruction_start")
    {
      if (open)
        throw EvaluationError(where + segments.back().name + " has no end before " + name);
      vrrw_demos::Segment segment;
      segment.name = name;
      segment.start = segment.end = event.time;
      segment.gripper = isGripperInstruction(name);
      segments.push_back(segment);
      open = true;
    }
    else if (kind == "instruction_end" || kind == "instruction_failed")
    {
      if (!open || segments.back().name != name)
        throw EvaluationError(where + "the end of " + name + " without its start");
      segments.back().end = event.time;
      open = false;
    }
  }
  if (open)
    throw EvaluationError(where + segments.back().name + " has no end");
  return segments;
}
}  // namespace vrrw_evaluation
