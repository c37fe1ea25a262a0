#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/replay_path.h>
#include <vrrw_demos/segmentation.h>

#include "scripted_demo.h"

using namespace vrrw_demos;

TEST(ReplayPath, SmoothsWithinToleranceAndKeepsTheRecordedTiming)
{
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(1000.0, 5e-4).demo.robots[0];
  ReplayOptions options;
  options.max_velocity.assign(6, 3.14);
  options.max_acceleration.assign(6, 10.0);
  const ReplayPath path = replayPath(track, options);
  EXPECT_LE(path.max_deviation, 1e-3 + 1e-15);
  EXPECT_GT(path.max_deviation, 1e-4);  // it did smooth the jitter
  EXPECT_DOUBLE_EQ(path.time_scale, 1.0);
  EXPECT_TRUE(path.stretches.empty()) << path.retimingSummary();
  EXPECT_NEAR(path.trajectory.duration(), 10.0, 1e-9);
  EXPECT_NEAR(path.trajectory.points.size(), 1001u, 2);
  // Jitter of 5e-4 rad at 1 kHz is 1 rad/s of velocity noise; smoothed, the velocities follow the script.
  double worst = 0.0;
  for (const auto& point : path.trajectory.points)
  {
    const RobotState truth = stateAt(track, point.time);
    for (std::size_t j = 0; j < 6; ++j)
      worst = std::max(worst, std::abs(point.velocities[j] - truth.velocities[j]));
  }
  EXPECT_LT(worst, 0.1);
}

namespace
{
/// The largest velocity and acceleration (as the retiming measures them) relative to the limits.
double worstRatio(const ReplayPath& path, const ReplayOptions& options)
{
  const auto& points = path.trajectory.points;
  double worst = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k)
    for (std::size_t j = 0; j < 6; ++j)
    {
      worst = std::max(worst, std::abs(points[k].velocities[j]) / options.max_velocity[j]);
      const double a = (points[k].velocities[j] - points[k - 1].velocities[j]) / (points[k].time - points[k - 1].time);
      worst = std::max(worst, std::abs(a) / options.max_acceleration[j]);
    }
  return worst;
}

std::string errorOf(const RobotTrack& track, const ReplayOptions& options)
{
  try
  {
    replayPath(track, options);
  }
  catch (const DemoError& e)
  {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(ReplayPath, StretchesOnlyWhereAVelocityLimitIsBrokenAndSaysWhichAndByHowMuch)
{
  // final (6.4-8.4 s) pans 1.1 rad in 2 s: minimum jerk peaks at 1.875 * 1.1 / 2 = 1.03 rad/s, over a
  // limit of 0.9; every other motion stays below 0.8 rad/s.
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(250.0, 0.0).demo.robots[0];
  ReplayOptions options;
  options.max_velocity.assign(6, 0.9);
  options.max_acceleration.assign(6, 100.0);
  const ReplayPath path = replayPath(track, options);
  std::cout << "0.9 rad/s: " << path.retimingSummary() << "\n";
  ASSERT_EQ(path.stretches.size(), 1u) << path.retimingSummary();
  const Stretch& stretch = path.stretches[0];
  EXPECT_EQ(stretch.limit, "ur5e_shoulder_pan_joint velocity");
  EXPECT_GT(stretch.start, 6.4);
  EXPECT_LT(stretch.end, 8.4);
  EXPECT_NEAR(stretch.factor, 1.03 / 0.9, 0.02);  // measured 1.143
  EXPECT_LE(worstRatio(path, options), 1.0);
  // everything before the stretch keeps the recorded timing exactly, everything after it is shifted by it
  const auto& points = path.trajectory.points;
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (path.recorded_times[k] <= stretch.start)
    {
      ASSERT_NEAR(points[k].time, path.recorded_times[k], 1e-9) << k;
    }
    else if (path.recorded_times[k] >= stretch.end)
    {
      ASSERT_NEAR(points[k].time, path.recorded_times[k] + stretch.added, 1e-9) << k;
    }
  }
  EXPECT_NEAR(path.trajectory.duration(), 10.0 + stretch.added, 1e-9);
  EXPECT_GT(stretch.added, 0.03);  // measured 0.06 s
  EXPECT_LT(stretch.added, 0.15);
  EXPECT_NEAR(path.time_scale, path.trajectory.duration() / 10.0, 1e-12);
  EXPECT_NE(path.retimingSummary().find("1 stretch slowed into the limits"), std::string::npos) << path.retimingSummary();
  // the time maps both ways through the stretch
  for (double recorded : { 1.0, 7.0, 9.0 })
    EXPECT_NEAR(path.recordedTime(path.replayTime(recorded)), recorded, 1e-9);
}

TEST(ReplayPath, StretchesOnlyTheMotionsThatBreakAnAccelerationLimit)
{
  // pick and back_to_near_pick move wrist_1 0.4 rad in 1 s: 5.77 * 0.4 = 2.31 rad/s^2 at their peaks, over
  // a limit of 2 (speeding up and slowing down, one stretch with the easing); near_pick and final stay below
  // 1.6 rad/s^2.
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(250.0, 0.0).demo.robots[0];
  ReplayOptions options;
  options.max_velocity.assign(6, 3.14);
  options.max_acceleration.assign(6, 2.0);
  const ReplayPath path = replayPath(track, options);
  std::cout << "2 rad/s^2: " << path.retimingSummary() << "\n";
  ASSERT_EQ(path.stretches.size(), 2u) << path.retimingSummary();
  EXPECT_GT(path.stretches[0].start, 2.6 - 0.25);  // pick, 2.6-3.6 s, and its easing
  EXPECT_LT(path.stretches[0].end, 3.6 + 0.25);
  EXPECT_GT(path.stretches[1].start, 4.9 - 0.25);  // back_to_near_pick, 4.9-5.9 s
  EXPECT_LT(path.stretches[1].end, 5.9 + 0.25);
  for (const Stretch& stretch : path.stretches)
  {
    EXPECT_NE(stretch.limit.find("acceleration"), std::string::npos) << stretch.limit;
    EXPECT_GT(stretch.factor, 1.075);  // sqrt(2.31 / 2) = 1.075, eased in: measured 1.093-1.097
    EXPECT_LT(stretch.factor, 1.15);
  }
  EXPECT_LE(worstRatio(path, options), 1.0);
  EXPECT_LT(path.time_scale, 1.03);  // measured 1.011: 0.11 s added to 10 s
}

TEST(ReplayPath, SpeedChangesThePaceWithinTheLimits)
{
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(250.0, 0.0).demo.robots[0];
  ReplayOptions options;
  options.max_velocity.assign(6, 3.14);
  options.max_acceleration.assign(6, 10.0);
  for (double speed : { 0.5, 2.0 })
  {
    options.speed = speed;
    const ReplayPath path = replayPath(track, options);
    EXPECT_TRUE(path.stretches.empty()) << speed << ": " << path.retimingSummary();
    EXPECT_NEAR(path.trajectory.duration(), 10.0 / speed, 1e-9);
    EXPECT_DOUBLE_EQ(path.time_scale, 1.0);
  }
  // at speed 4 the limits slow only the fast parts: the replay is shorter than at 2, longer than 10 / 4
  options.speed = 4.0;
  const ReplayPath fast = replayPath(track, options);
  std::cout << "speed 4: " << fast.retimingSummary() << "\n";
  EXPECT_FALSE(fast.stretches.empty());
  EXPECT_GT(fast.trajectory.duration(), 2.5);
  EXPECT_LT(fast.trajectory.duration(), 5.0);
  EXPECT_LE(worstRatio(fast, options), 1.0);
}

TEST(ReplayPath, RefusesSpeedsTolerancesAndLimitsOutsideTheBounds)
{
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(50.0, 0.0).demo.robots[0];
  ReplayOptions options;
  options.max_velocity.assign(6, 1.0);
  options.max_acceleration.assign(6, 1.0);
  for (double speed : { std::numeric_limits<double>::infinity(), 1e-300, std::nan(""), 0.0, -1.0, 10.5 })
  {
    options.speed = speed;
    EXPECT_EQ(errorOf(track, options).rfind("speed: ", 0), 0u) << speed << ": " << errorOf(track, options);
  }
  options.speed = 1.0;
  options.tolerance = 1e9;
  EXPECT_EQ(errorOf(track, options), "tolerance: 1e+09 rad is outside [0, 0.01]");
  options.tolerance = 1e-3;
  options.max_velocity[2] = 0.0;
  EXPECT_EQ(errorOf(track, options), "robot 'ur5e': joint ur5e_elbow_joint: limit 0 is not positive");
  options.max_velocity.assign(5, 1.0);
  EXPECT_EQ(errorOf(track, options), "robot 'ur5e': limits for 5 joints, the recording has 6");
  options.max_velocity.assign(6, 1.0);
  options.speed = 0.1;
  RobotTrack long_track = track;
  long_track.states.back().time = 400.0;  // 400 s at a tenth: 4000 s
  EXPECT_EQ(errorOf(long_track, options),
            "robot 'ur5e': 400 s recorded at speed 0.1 would last more than the bound of 3600 s");
}
