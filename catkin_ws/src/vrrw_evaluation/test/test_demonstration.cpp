#include <vrrw_evaluation/demonstration.h>
#include <vrrw_evaluation/instruction_dmps.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace vrrw_evaluation;

namespace
{
/// Two joints; 0..1 s a smooth move, 1..1.5 s still (a gripper instruction), 1.5..2.5 s back.
Demonstration pickLike()
{
  Demonstration demo;
  demo.arm.joint_names = { "a", "b" };
  for (int k = 0; k <= 250; ++k)
  {
    const double t = k * 0.01;
    const double s = t < 1.0 ? t : (t < 1.5 ? 1.0 : std::max(0.0, 2.5 - t));
    const double blend = s * s * s * (10 - 15 * s + 6 * s * s);
    demo.arm.points.push_back({ t, { 0.5 * blend, -0.3 * blend + 0.1 * std::sin(M_PI * s) }, {}, {} });
  }
  demo.segments = { { "move_to_near_pick", 0.0, 1.0 }, { "close_gripper", 1.0, 1.5 }, { "back_to_near_pick", 1.5, 2.5 } };
  return demo;
}
}  // namespace

TEST(Demonstration, SliceRebasesAndInterpolatesItsEnds)
{
  const Demonstration demo = pickLike();
  const auto part = slice(demo.arm, 0.505, 1.0);
  EXPECT_DOUBLE_EQ(part.points.front().time, 0.0);
  EXPECT_NEAR(part.duration(), 0.495, 1e-12);
  const auto expected = positionsAt(demo.arm, 0.505);
  EXPECT_NEAR(part.points.front().positions[0], expected[0], 1e-15);
  EXPECT_NEAR(expected[0], 0.5 * (positionsAt(demo.arm, 0.50)[0] + positionsAt(demo.arm, 0.51)[0]), 1e-15);
  // A recorded sample 0.1 ms after the start is left out: no near-zero interval in a goal.
  const auto close = slice(demo.arm, 0.4999, 0.8);
  EXPECT_NEAR(close.points[1].time, 0.0101, 1e-9);
  for (std::size_t k = 1; k < close.points.size(); ++k)
    EXPECT_GE(close.points[k].time - close.points[k - 1].time, kEndGap - 1e-12);
  EXPECT_THROW(slice(demo.arm, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(demo.segment("open_gripper"), std::invalid_argument);
}

TEST(Demonstration, JointRmsOfAShiftedCopyIsTheShift)
{
  const Demonstration demo = pickLike();
  auto shifted = demo.arm;
  for (auto& p : shifted.points)
    p.positions[0] += 0.002, p.positions[1] -= 0.002, p.time += 3.0;  // its own start: only the offset counts
  EXPECT_NEAR(jointRms(demo.arm, shifted), 0.002, 1e-12);
  EXPECT_NEAR(jointRms(demo.arm, demo.arm), 0.0, 1e-15);
  const auto thinned = thin(demo.arm, 0.05);
  EXPECT_EQ(thinned.points.size(), 51u);
  EXPECT_DOUBLE_EQ(thinned.points.back().time, 2.5);
}

TEST(InstructionDmps, OneModelPerArmInstructionReproducesAndReachesNewGoals)
{
  const Demonstration demo = pickLike();
  vrrw_dmp::DmpParameters parameters;
  parameters.basis_count = 30;
  parameters.scaling = vrrw_dmp::AmplitudeScaling::automatic;
  const InstructionDmps dmps(demo, parameters);
  ASSERT_EQ(dmps.instructions().size(), 2u);  // the gripper instruction has no arm DMP
  EXPECT_LT(dmps.fitRmse("move_to_near_pick"), 5e-3);  // 1 % of the 0.5 rad move (30 basis functions)
  EXPECT_LT(dmps.fitRmse("back_to_near_pick"), 5e-3);
  const auto rollout = dmps.rollout("move_to_near_pick", { 0.0, 0.0 }, { 0.6, -0.2 });
  // Ends exactly at the goal, at rest, without the spring's slow tail (at most tau + 0.2 s after settling).
  EXPECT_EQ(rollout.points.back().positions, (std::vector<double>{ 0.6, -0.2 }));
  EXPECT_EQ(rollout.points.back().velocities, (std::vector<double>{ 0.0, 0.0 }));
  EXPECT_LT(rollout.duration(), 2.0);
  const auto& before = rollout.points[rollout.points.size() - 2].positions;
  EXPECT_LT(std::max(std::abs(before[0] - 0.6), std::abs(before[1] + 0.2)), InstructionDmps::kSettledWithin);
  EXPECT_NEAR(rollout.points.front().positions[0], 0.0, 1e-12);
  EXPECT_THROW(dmps.dmp("close_gripper"), std::invalid_argument);
}

TEST(InstructionDmps, ARolloutOverTheVelocityLimitsIsSlowedDownToThem)
{
  vrrw_dmp::DmpParameters parameters;
  parameters.basis_count = 30;
  parameters.scaling = vrrw_dmp::AmplitudeScaling::automatic;
  const InstructionDmps dmps(pickLike(), parameters);
  auto peak = [](const vrrw_trajectory::JointTrajectory& motion, std::size_t j) {
    double largest = 0.0;
    for (const auto& p : motion.points)
      largest = std::max(largest, std::abs(p.velocities[j]));
    return largest;
  };
  // Three times the demonstrated 0.5 rad: about three times as fast, over a 1.2 rad/s limit on joint a.
  const std::vector<double> start{ 0.0, 0.0 }, goal{ 1.5, -0.2 }, limits{ 1.2, 10.0 };
  const auto free = dmps.rollout("move_to_near_pick", start, goal);
  const auto bounded = dmps.rollout("move_to_near_pick", start, goal, 0.01, limits);
  std::cout << "peak velocity of joint a: " << peak(free, 0) << " rad/s unbounded, " << peak(bounded, 0)
            << " rad/s within 0.9 x 1.2, over " << bounded.duration() << " s instead of " << free.duration() << " s\n";
  EXPECT_GT(peak(free, 0), 1.2);
  EXPECT_LT(peak(bounded, 0), 1.2);
  // slowed just enough: the margin below the limit, up to where the 10 ms samples catch the peak
  EXPECT_NEAR(peak(bounded, 0), InstructionDmps::kVelocityMargin * 1.2, 0.01 * 1.2);
  EXPECT_EQ(bounded.points.back().positions, goal);
  // Within the limits nothing changes (a peak of 1.13 rad/s on joint a).
  const auto same = dmps.rollout("move_to_near_pick", start, { 0.6, -0.2 }, 0.01, { 3.0, 10.0 });
  EXPECT_EQ(same.duration(), dmps.rollout("move_to_near_pick", start, { 0.6, -0.2 }).duration());
}
