#include <gtest/gtest.h>

#include <cmath>

#include <vrrw_demos/segmentation.h>

#include "hesitant_demo.h"
#include "scripted_demo.h"

using namespace vrrw_demos;

namespace
{
/// Every boundary of every instruction within 50 ms of the script's, in the paper's order.
void expectBoundaries(const vrrw_demos_test::ScriptedDemo& scripted, const Segmentation& found)
{
  ASSERT_EQ(found.segments.size(), scripted.truth.size());
  double worst = 0.0;
  for (std::size_t s = 0; s < found.segments.size(); ++s)
  {
    const Segment& segment = found.segments[s];
    EXPECT_EQ(segment.name, scripted.truth[s].first);
    worst = std::max({ worst, std::abs(segment.start - scripted.truth[s].second.first),
                       std::abs(segment.end - scripted.truth[s].second.second) });
    EXPECT_NEAR(segment.start, scripted.truth[s].second.first, 0.05) << segment.name;
    EXPECT_NEAR(segment.end, scripted.truth[s].second.second, 0.05) << segment.name;
  }
  testing::Test::RecordProperty("worst_boundary_error_ms", std::to_string(worst * 1e3));
  std::cout << "worst boundary error: " << worst * 1e3 << " ms\n";
}
}  // namespace

TEST(Segmentation, ScriptedPickPlaceFromGripperGoals)
{
  const auto scripted = vrrw_demos_test::scriptedPickPlace();
  const Segmentation found = segmentPickPlace(scripted.demo.robots[0], scripted.demo);
  expectBoundaries(scripted, found);
  EXPECT_TRUE(found.warnings.empty());
  for (const Segment& segment : found.segments)
  {
    if (segment.name != std::string("near_pick") && segment.name != std::string("pick"))
    {
      EXPECT_EQ(segment.object, "drill") << segment.name;
    }
  }
  EXPECT_TRUE(found.segments[2].gripper);
  EXPECT_DOUBLE_EQ(found.segments[2].gripper_target, 0.8);
}

TEST(Segmentation, ScriptedPickPlaceFromGripperMotionAt1kHz)
{
  auto scripted = vrrw_demos_test::scriptedPickPlace(1000.0, 5e-4, 3);
  scripted.demo.robots[0].gripper_goals.clear();
  expectBoundaries(scripted, segmentPickPlace(scripted.demo.robots[0], scripted.demo));
}

TEST(Segmentation, WaypointStopsStayInTheirInstruction)
{
  // near_pick stops halfway, final above the place: pick is the motion into the grasp, back_to_near_pick the
  // motion out of it, whatever stops the others make
  const auto scripted = vrrw_demos_test::scriptedPickPlace(250.0, 2e-4, 1, true);
  const Segmentation found = segmentPickPlace(scripted.demo.robots[0], scripted.demo);
  expectBoundaries(scripted, found);
  EXPECT_TRUE(found.warnings.empty());
}

TEST(Segmentation, WithoutBackToNearPickAndWithoutGripperSaysWhy)
{
  auto scripted = vrrw_demos_test::scriptedPickPlace();
  RobotTrack& track = scripted.demo.robots[0];
  for (RobotState& state : track.states)
    state.gripper = 0.0;
  track.gripper_goals.clear();
  const Segmentation found = segmentPickPlace(track, scripted.demo);
  ASSERT_EQ(found.segments.size(), 2u);  // near_pick, pick: the arm moved four times, nothing closed
  ASSERT_EQ(found.warnings.size(), 1u);
  EXPECT_EQ(found.warnings[0], "robot 'ur5e': the gripper never moved: no close_gripper");
}

TEST(Segmentation, AGraspThatStallsSetsTheClosingDirectionEvenBeforeTheArmMoves)
{
  auto scripted = vrrw_demos_test::scriptedPickPlace();
  RobotTrack& track = scripted.demo.robots[0];
  // An open goal at 0.1 s that opens nothing more, then the scripted close stops at 0.5 of its 0.8 goal.
  for (RobotState& state : track.states)
    state.gripper = std::min(state.gripper, 0.5);
  track.gripper_goals.insert(track.gripper_goals.begin(), GripperGoal{ 0.1, 0.0 });
  const Segmentation found = segmentPickPlace(track, scripted.demo);
  ASSERT_EQ(found.segments.size(), 6u);
  EXPECT_EQ(found.segments[2].name, "close_gripper");
  EXPECT_DOUBLE_EQ(found.segments[2].start, 3.9);
  EXPECT_EQ(found.segments[5].name, "open_gripper");
  EXPECT_DOUBLE_EQ(found.segments[5].start, 8.8);
}

TEST(Segmentation, SliceKeepsTimesAndInterpolatesEnds)
{
  const auto scripted = vrrw_demos_test::scriptedPickPlace();
  const RobotTrack part = slice(scripted.demo.robots[0], 2.601, 3.6);
  EXPECT_DOUBLE_EQ(part.states.front().time, 2.601);
  EXPECT_DOUBLE_EQ(part.states.back().time, 3.6);
  EXPECT_EQ(part.gripper_goals.size(), 0u);
}

TEST(Segmentation, AHesitantTeacherKeepsEachInstructionWhole)
{
  // pauses of 1-10 s inside and between instructions, a twitch and a ringing hold: the boundaries the
  // teacher's moves had, within 50 ms
  const auto scripted = vrrw_demos_test::hesitantPickPlace();
  const Segmentation found = segmentPickPlace(scripted.demo.robots[0], scripted.demo);
  expectBoundaries(scripted, found);
  EXPECT_TRUE(found.warnings.empty());
  EXPECT_EQ(found.segments[3].object, "box");
}

TEST(Segmentation, WithoutTheTcpThePickIsTheLastMotionBeforeTheGrasp)
{
  auto scripted = vrrw_demos_test::hesitantPickPlace();
  scripted.demo.metadata.robot_description.clear();
  const Segmentation found = segmentPickPlace(scripted.demo.robots[0], scripted.demo);
  ASSERT_EQ(found.segments.size(), 6u);
  EXPECT_NEAR(found.segments[1].start, 9.8, 0.05);  // only the second half of the descent
  EXPECT_NEAR(found.segments[3].end, 14.1, 0.05);   // only the first half of the lift
}
