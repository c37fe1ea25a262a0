#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/time_parameterization.h"

using namespace vrrw_kinematics;

namespace
{
double distanceToPolyline(const Eigen::VectorXd& q, const std::vector<Eigen::VectorXd>& path)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    const Eigen::VectorXd d = path[i] - path[i - 1];
    const double t = std::max(0.0, std::min(1.0, (q - path[i - 1]).dot(d) / d.squaredNorm()));
    best = std::min(best, (q - path[i - 1] - t * d).norm());
  }
  return best;
}

void expectWithinLimits(const vrrw_trajectory::JointTrajectory& trajectory, const TimingOptions& options)
{
  ASSERT_GE(trajectory.points.size(), 2u);
  const std::size_t n = options.max_velocity.size();
  for (std::size_t k = 0; k < trajectory.points.size(); ++k)
  {
    const auto& point = trajectory.points[k];
    for (std::size_t i = 0; i < n; ++i)
    {
      EXPECT_LE(std::abs(point.velocities[i]), options.max_velocity[i] * (1 + 1e-9)) << "sample " << k;
      EXPECT_LE(std::abs(point.accelerations[i]), options.max_acceleration[i] * (1 + 1e-9)) << "sample " << k;
    }
    if (k == 0)
      continue;
    const auto& previous = trajectory.points[k - 1];
    const double dt = point.time - previous.time;
    EXPECT_GT(dt, 0.0);
    for (std::size_t i = 0; i < n; ++i)
    {
      // Positions advance by the mean of the two velocities (exact for constant acceleration).
      const double predicted = 0.5 * (point.velocities[i] + previous.velocities[i]) * dt;
      EXPECT_NEAR(point.positions[i] - previous.positions[i], predicted, options.max_acceleration[i] * dt * dt);
    }
  }
  for (const double v : trajectory.points.front().velocities)
    EXPECT_EQ(v, 0.0);
  for (const double v : trajectory.points.back().velocities)
    EXPECT_EQ(v, 0.0);
}
}  // namespace

TEST(TimeParameterization, SingleJointTrapezoidIsTimeOptimal)
{
  TimingOptions options;
  options.max_velocity = { 1.0 };
  options.max_acceleration = { 2.0 };
  const auto trajectory = TimeParameterization(options).compute({ vec({ 0.0 }), vec({ 1.0 }) }, { "j" });
  // Accelerate 0.5 s to 1 rad/s, cruise 0.5 s, decelerate 0.5 s: 1.5 s at the full limits.
  EXPECT_GT(trajectory.duration(), 1.5);
  EXPECT_LT(trajectory.duration(), 1.5 / options.safety + 0.01);
  EXPECT_DOUBLE_EQ(trajectory.points.back().positions[0], 1.0);
  expectWithinLimits(trajectory, options);
}

TEST(TimeParameterization, BlendedCornersRespectLimitsAndDeviation)
{
  TimingOptions options;
  options.max_velocity = { 1.0, 0.8, 2.0 };
  options.max_acceleration = { 3.0, 2.0, 4.0 };
  options.max_deviation = 0.05;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    std::vector<Eigen::VectorXd> path;
    for (int w = 0; w < 5; ++w)
      path.push_back(vec({ uniform(rng), uniform(rng), uniform(rng) }));
    const auto trajectory = TimeParameterization(options).compute(path, { "a", "b", "c" });
    expectWithinLimits(trajectory, options);
    for (const auto& point : trajectory.points)
    {
      const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(point.positions.data(), 3);
      EXPECT_LE(distanceToPolyline(q, path), options.max_deviation + 1e-9);
    }
    EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(trajectory.points.back().positions.data(), 3) - path.back()).norm(),
              1e-12);
  }
}

TEST(TimeParameterization, StopsAtCornersWithoutBlends)
{
  TimingOptions options;
  options.max_velocity = { 1.0, 1.0 };
  options.max_acceleration = { 2.0, 2.0 };
  options.max_deviation = 0.0;
  const std::vector<Eigen::VectorXd> path = { vec({ 0, 0 }), vec({ 1, 0 }), vec({ 1, 1 }) };
  const auto trajectory = TimeParameterization(options).compute(path, { "a", "b" });
  expectWithinLimits(trajectory, options);
  double nearest = 1.0;
  for (const auto& point : trajectory.points)
  {
    nearest = std::min(nearest, std::hypot(point.positions[0] - 1.0, point.positions[1]));
    EXPECT_LE(distanceToPolyline(Eigen::Map<const Eigen::VectorXd>(point.positions.data(), 2), path), 1e-9);
  }
  EXPECT_LT(nearest, 1e-3);
  // Two 1 rad rest-to-rest moves of 1.5 s each.
  EXPECT_GT(trajectory.duration(), 3.0);
}

TEST(TimeParameterization, BadInputIsRejected)
{
  TimingOptions options;
  options.max_velocity = { 1.0 };
  options.max_acceleration = { 0.0 };
  EXPECT_THROW(TimeParameterization{ options }, KinematicsError);
  options.max_acceleration = { 1.0, 1.0 };
  EXPECT_THROW(TimeParameterization{ options }, KinematicsError);
  options.max_acceleration = { 1.0 };
  const TimeParameterization timing(options);
  EXPECT_THROW(timing.compute({}, { "j" }), KinematicsError);
  EXPECT_THROW(timing.compute({ vec({ 0.0 }), vec({ std::nan("") }) }, { "j" }), KinematicsError);
  EXPECT_THROW(timing.compute({ vec({ 0.0, 1.0 }) }, { "j" }), KinematicsError);
  EXPECT_THROW(timing.compute({ vec({ 0.0 }) }, { "j", "k" }), KinematicsError);
  EXPECT_EQ(timing.compute({ vec({ 0.5 }), vec({ 0.5 }) }, { "j" }).points.size(), 1u);
}
