#pragma once
// How well a DMP reproduces the demonstration it was learned from, and what would reproduce it better.
#include <string>
#include <utility>
#include <vector>

#include <vrrw_dmp/dmp.h>
#include <vrrw_dmp/dmp_parameters.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_dmp
{
/// \brief A demonstration to learn from, as `vrrw_dmp learn` and dmp_node's ~learn read it (a CSV, or a
/// robot's track or one instruction of a recorded bag: src/ros/demo_source.h).
struct DemoSource
{
  vrrw_trajectory::JointTrajectory trajectory;  ///< the arm's joints, times from the recording's start
  std::string source;  ///< for the model's provenance: "demo.csv" or "demo.bag robot ur5e segment pick 3.2-5.1 s"
  /// the arm's motions between rests (keyframe rule), s: more than one means a poor fit is a segment's job
  std::vector<std::pair<double, double>> motions;
  std::vector<std::string> segments;  ///< bags: the instructions found, for advice
  bool from_bag = false;
};

/// rad RMS: a reproduction worse than this gets advice (a segment, a basis count).
constexpr double kGoodFit = 0.01;

/// \brief The largest RMSE over joints of \a demo against \a dmp rolled out as demonstrated (its start, goal
/// and duration), the rollout linearly interpolated at the demonstration's time stamps.
double reproductionRmse(const Dmp& dmp, const vrrw_trajectory::JointTrajectory& demo);

/// \brief What would reproduce \a demo better than \a rmse (none at or below kGoodFit): one motion at a time
/// when it holds several (naming the bag's instructions for --segment), and the smallest doubled basis count up
/// to 1000 that reproduces it within kGoodFit, or that none does.
std::vector<std::string> fitAdvice(const DemoSource& demo, const DmpParameters& parameters, double rmse);
}  // namespace vrrw_dmp
