#pragma once
// Stage 2 of ./vrrw demo: the instructions as the demonstration's bag records them.
#include <vector>

#include <vrrw_demos/demonstration.h>
#include <vrrw_demos/segmentation.h>

namespace vrrw_evaluation
{
/// \brief The instructions the runner annotated in a recorded demonstration (read by vrrw_demos), in order, in s
/// from the recording's start: its events of kind instruction_start / instruction_end / instruction_failed with
/// the name as detail (the runner's own), or of kind annotate with the text "instruction_start <name>" (vrrw_demos'
/// recorder). Throws std::runtime_error "<bag>: /demos/events: <reason>" for an instruction without its end, one
/// that starts before the last ended, or an end without its start.
std::vector<vrrw_demos::Segment> annotatedInstructions(const vrrw_demos::Demonstration& demo);
}  // namespace vrrw_evaluation
