#pragma once
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_demos
{
/// \brief How a recorded track becomes a trajectory a controller accepts.
struct ReplayOptions
{
  double tolerance = 1e-3;          ///< rad (m): the smoothed path stays this close to every recorded sample
  double min_point_spacing = 0.01;  ///< s between trajectory points (recordings at 1 kHz are thinned to 100 Hz)
  double speed = 1.0;               ///< > 1 replays faster than recorded
  std::vector<double> max_velocity;      ///< per joint; empty: no check
  std::vector<double> max_acceleration;  ///< per joint; empty: no check
};

/// \brief The replayed path and what was done to it.
struct ReplayPath
{
  vrrw_trajectory::JointTrajectory trajectory;  ///< times from 0, positions and velocities
  double max_deviation = 0.0;  ///< rad: the largest |smoothed - recorded| over all samples and joints
  double time_scale = 1.0;     ///< >= 1: how much slower than (recorded / speed) the limits made it
  std::string limiting;        ///< the joint and limit that set time_scale; empty when 1
};

/// \brief De-jitter (binomial smoothing clamped to the tolerance around the recorded samples, ends kept),
/// thin to min_point_spacing, velocities by central differences, then retime: the recorded timing divided
/// by speed, stretched uniformly until every joint's velocity and acceleration is within its limit.
/// Throws DemoError for a track with fewer than two states or limits of the wrong size.
ReplayPath replayPath(const RobotTrack& track, const ReplayOptions& options);
}  // namespace vrrw_demos
