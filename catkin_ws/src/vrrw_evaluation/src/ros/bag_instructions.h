#pragma once
// Stage 2 of ./vrrw demo: the instructions as the demonstration's bag records them.
#include <string>
#include <vector>
#include <vrrw_evaluation/demonstration.h>

namespace vrrw_evaluation
{
/// \brief The instructions annotated in a recorded bag, in order, in s from `start_stamp` (the recording's
/// start, s of ROS time): /demos/events as the runner writes them (kind instruction_start / instruction_end,
/// detail the name) or as vrrw_demos' recorder does (kind annotate, text "instruction_start <name>").
/// Throws std::runtime_error naming the bag and what is wrong (unreadable, an instruction without its end).
std::vector<Segment> bagInstructions(const std::string& bag, double start_stamp);
}  // namespace vrrw_evaluation
