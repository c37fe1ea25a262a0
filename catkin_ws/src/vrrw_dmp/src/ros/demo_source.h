#pragma once
// What `vrrw_dmp learn` and dmp_node's ~learn learn from: a CSV, or a robot's track (or one instruction of
// it) in a recorded bag, read through vrrw_demos' one bag reader.
#include <string>

#include <vrrw_dmp/demo_fit.h>

namespace vrrw_dmp
{
/// \brief A CSV (vrrw_trajectory/csv.h). Throws its TrajectoryError naming the file and line.
DemoSource csvSource(const std::string& path);

/// \brief Robot \a robot's track (empty: the bag's only robot) of a recorded bag, or its instruction named
/// \a segment. Throws vrrw_demos::DemoError naming the bag, the robot or the segment (listing those found).
DemoSource bagSource(const std::string& bag, const std::string& robot, const std::string& segment);
}  // namespace vrrw_dmp
