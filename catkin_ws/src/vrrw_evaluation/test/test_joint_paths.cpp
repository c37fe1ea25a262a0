#include <vrrw_evaluation/joint_paths.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace vrrw_evaluation;

namespace
{
/// Two joints; 0..1 s a smooth move, 1..1.5 s still (a gripper instruction), 1.5..2.5 s back.
vrrw_trajectory::JointTrajectory pickLike()
{
  vrrw_trajectory::JointTrajectory arm;
  arm.joint_names = { "a", "b" };
  for (int k = 0; k <= 250; ++k)
  {
    const double t = k * 0.01;
    const double s = t < 1.0 ? t : (t < 1.5 ? 1.0 : std::max(0.0, 2.5 - t));
    const double blend = s * s * s * (10 - 15 * s + 6 * s * s);
    arm.points.push_back({ t, { 0.5 * blend, -0.3 * blend + 0.1 * std::sin(M_PI * s) }, {}, {} });
  }
  return arm;
}
}  // namespace

TEST(JointPaths, AnInstructionGoalRebasesAndInterpolatesItsEnds)
{
  const auto arm = pickLike();
  const auto track = asTrack(arm, "r");
  const auto part = instructionGoal(track, 0.505, 1.0);
  EXPECT_DOUBLE_EQ(part.points.front().time, 0.0);
  EXPECT_NEAR(part.duration(), 0.495, 1e-12);
  EXPECT_NEAR(part.points.front().positions[0], 0.5 * (positionsAt(arm, 0.50)[0] + positionsAt(arm, 0.51)[0]), 1e-15);
  for (double v : part.points.back().velocities)
    EXPECT_EQ(v, 0.0);  // at rest at the ends
  // A recorded sample 0.1 ms after the start is left out: no near-zero interval in a goal.
  const auto close = instructionGoal(track, 0.4999, 0.8);
  EXPECT_NEAR(close.points[1].time, 0.0101, 1e-9);
  for (std::size_t k = 1; k < close.points.size(); ++k)
    EXPECT_GE(close.points[k].time - close.points[k - 1].time, 0.005 - 1e-12);
}

TEST(JointPaths, JointRmsOfAShiftedCopyIsTheShift)
{
  const auto arm = pickLike();
  auto shifted = arm;
  for (auto& p : shifted.points)
    p.positions[0] += 0.002, p.positions[1] -= 0.002, p.time += 3.0;  // its own start: only the offset counts
  EXPECT_NEAR(jointRms(arm, shifted), 0.002, 1e-12);
  EXPECT_NEAR(jointRms(arm, arm), 0.0, 1e-15);
  const auto thinned = thin(arm, 0.05);
  EXPECT_EQ(thinned.points.size(), 51u);
  EXPECT_DOUBLE_EQ(thinned.points.back().time, 2.5);
}
