#pragma once
#include <string>
#include <vector>

#include <vrrw_demos/replay_path.h>
#include <vrrw_demos/segmentation.h>

namespace vrrw_demos
{
/// \brief The arm instruction (segment) under way at \a time (s from the demonstration's start):
/// its name, "rest" between instructions, "" when \a instructions name none.
std::string instructionAt(const std::vector<Segment>& instructions, double time);

/// \brief "name, 42 %, 12.3 s left" for \a elapsed of \a duration s.
std::string progressText(const std::string& name, double elapsed, double duration);

/// \brief A progress line of a replay at replay time \a t: "pick, 42 %, 12.3 s left". \a first_state is
/// the demonstration time of the path's first point (the instructions' clock).
std::string progressLine(const ReplayPath& path, const std::vector<Segment>& instructions, double first_state,
                         double t);
}  // namespace vrrw_demos
