#include <gtest/gtest.h>

#include <cmath>

#include <vrrw_skills/skill_learning.h>

namespace
{
/// One joint: 0 -> 1 rad in 1 s, a pause of `pause` s (with 0.1 mrad of jitter), 1 -> 2 rad in 1 s, at 100 Hz.
vrrw_demos::RobotTrack hesitantTrack(double pause)
{
  vrrw_demos::RobotTrack track;
  track.robot = "arm";
  track.joint_names = { "joint" };
  const double total = 2.0 + pause;
  for (int k = 0; k <= int(total * 100); ++k)
  {
    const double t = k * 0.01;
    auto jerk = [](double u) { u = std::clamp(u, 0.0, 1.0); return u * u * u * (10 - 15 * u + 6 * u * u); };
    const double q = jerk(t) + jerk(t - 1.0 - pause) + (t > 1.0 && t < 1.0 + pause ? 1e-4 * std::sin(40.0 * t) : 0.0);
    track.states.push_back({ t, { q }, { 0.0 }, 0.0 });
  }
  for (std::size_t k = 1; k + 1 < track.states.size(); ++k)
    track.states[k].velocities[0] = (track.states[k + 1].positions[0] - track.states[k - 1].positions[0]) / 0.02;
  return track;
}
}  // namespace

TEST(SkillLearning, PausesAreCutOutOfAMotion)
{
  for (double pause : { 0.5, 3.0, 10.0 })
  {
    const auto track = hesitantTrack(pause);
    const auto motion = vrrw_skills::motionWithoutPauses(track, 0.0, track.states.back().time, 0.01,
                                                         vrrw_demos::SegmentationOptions{});
    // two 1 s motions and the 0.1 s bridge that replaces the pause (their walked-out ends add a few samples)
    EXPECT_NEAR(motion.duration(), 2.1, 0.15) << "pause " << pause;
    EXPECT_NEAR(motion.points.front().positions[0], 0.0, 1e-12);
    EXPECT_NEAR(motion.points.back().positions[0], 2.0, 1e-12);
    double largest_step = 0.0;
    for (std::size_t k = 1; k < motion.points.size(); ++k)
    {
      EXPECT_NEAR(motion.points[k].time - motion.points[k - 1].time, 0.01, 1e-9);
      largest_step = std::max(largest_step, std::abs(motion.points[k].positions[0] - motion.points[k - 1].positions[0]));
    }
    EXPECT_LT(largest_step, 0.02) << "pause " << pause;  // the fastest demonstrated step is 0.0188 rad
  }
}

TEST(SkillLearning, SkillDmpParametersAreTheDemosMeasuredOnes)
{
  const auto parameters = vrrw_skills::skillDmpParameters();
  EXPECT_EQ(parameters.basis_count, 30u);
  EXPECT_EQ(parameters.scaling, vrrw_dmp::AmplitudeScaling::automatic);
  EXPECT_EQ(parameters.still_range, 0.02);
}
