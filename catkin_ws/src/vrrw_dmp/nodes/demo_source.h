#pragma once
// What `vrrw_dmp learn` and dmp_node's ~learn learn from: a CSV, or a robot's track (or one instruction of
// it) in a recorded bag, read through vrrw_demos' one bag reader.
#include <string>
#include <utility>
#include <vector>

#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_dmp
{
struct DemoSource
{
  vrrw_trajectory::JointTrajectory trajectory;  ///< the arm's joints, times from the recording's start
  std::string source;  ///< for the model's provenance: "demo.csv" or "demo.bag robot ur5e segment pick 3.2-5.1 s"
  /// the arm's motions between rests (keyframe rule), s: more than one means a poor fit is a segment's job
  std::vector<std::pair<double, double>> motions;
  std::vector<std::string> segments;  ///< bags: the instructions found, for advice
  bool from_bag = false;
};

/// \brief A CSV (vrrw_trajectory/csv.h). Throws its TrajectoryError naming the file and line.
DemoSource csvSource(const std::string& path);

/// \brief Robot \a robot's track (empty: the bag's only robot) of a recorded bag, or its instruction named
/// \a segment. Throws vrrw_demos::DemoError naming the bag, the robot or the segment (listing those found).
DemoSource bagSource(const std::string& bag, const std::string& robot, const std::string& segment);
}  // namespace vrrw_dmp
