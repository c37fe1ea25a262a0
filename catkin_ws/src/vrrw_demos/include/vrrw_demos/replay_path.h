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

/// \brief The bounds replayPath() holds a request to (it refuses beyond them, naming the bound).
struct ReplayBounds
{
  static constexpr double kMinSpeed = 0.1, kMaxSpeed = 10.0;
  static constexpr double kMaxTolerance = 0.01;   ///< rad: more would be another path, not de-jitter
  static constexpr double kMaxDuration = 3600.0;  ///< s of replay (360 000 points at 100 Hz)
};

/// \brief A stretch of the recording the limits made slower: recorded times [start, end] (s from the
/// track's first state) and the largest factor by which its time intervals were stretched.
struct Stretch
{
  double start = 0.0, end = 0.0;
  double factor = 1.0;
  double added = 0.0;   ///< s of replay it added
  std::string limit;    ///< what set it: "<joint> velocity" or "<joint> acceleration"
};

/// \brief The replayed path and what was done to it.
struct ReplayPath
{
  vrrw_trajectory::JointTrajectory trajectory;  ///< times from 0, positions and velocities
  std::vector<double> recorded_times;  ///< per point: its time in the recording (s from the first state)
  double max_deviation = 0.0;  ///< rad: the largest |smoothed - recorded| over all samples and joints
  double time_scale = 1.0;     ///< replay duration / (recorded duration / speed): >= 1
  std::vector<Stretch> stretches;  ///< where the limits stretched the recorded timing, in time order
  double speed = 1.0;              ///< the requested speed (ReplayOptions::speed)

  /// \brief The recording's time (s from its first state) at replay time \a t (clamped to the path).
  double recordedTime(double t) const;
  /// \brief The replay time at which the recording's time \a recorded (s from its first state) is reached;
  /// beyond the path's ends at the requested speed (a gripper goal after the last state).
  double replayTime(double recorded) const;
  /// \brief One line: "the recorded timing" or which stretches were slowed, by how much and why.
  std::string retimingSummary() const;
};

/// \brief De-jitter (binomial smoothing clamped to the tolerance around the recorded samples, ends kept),
/// thin to min_point_spacing, velocities by central differences, then retime: the recorded timing divided
/// by speed wherever every joint's velocity and acceleration is within its limit; where not, only the
/// time intervals there are stretched (eased into over kEaseSeconds on each side) until they are.
/// Throws DemoError for a track with fewer than two states, limits of the wrong size, or a speed,
/// tolerance or resulting duration outside ReplayBounds.
ReplayPath replayPath(const RobotTrack& track, const ReplayOptions& options);
}  // namespace vrrw_demos
