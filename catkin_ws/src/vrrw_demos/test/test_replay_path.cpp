#include <gtest/gtest.h>

#include <cmath>

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

TEST(ReplayPath, StretchesUniformlyIntoTheLimitsAndSaysWhich)
{
  const RobotTrack track = vrrw_demos_test::scriptedPickPlace(250.0, 0.0).demo.robots[0];
  ReplayOptions options;
  options.speed = 4.0;
  options.max_velocity.assign(6, 1.0);
  options.max_acceleration.assign(6, 100.0);
  const ReplayPath path = replayPath(track, options);
  EXPECT_GT(path.time_scale, 1.0);
  EXPECT_NE(path.limiting.find("velocity"), std::string::npos);
  for (const auto& point : path.trajectory.points)
    for (double v : point.velocities)
      EXPECT_LE(std::abs(v), 1.0);
  EXPECT_NEAR(path.trajectory.duration(), 10.0 / 4.0 * path.time_scale, 1e-9);
  options.max_velocity.assign(5, 1.0);
  EXPECT_THROW(replayPath(track, options), DemoError);
}
