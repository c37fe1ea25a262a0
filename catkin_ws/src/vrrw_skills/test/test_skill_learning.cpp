#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_learning.h>

#include "skill_fixture.h"

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
    // two 1 s motions and the pause, cut to 0.5 s where it was longer (their walked-out ends add a few samples)
    EXPECT_NEAR(motion.duration(), 2.0 + std::min(pause, 0.5), 0.15) << "pause " << pause;
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

namespace
{
std::string refusalOf(const std::vector<vrrw_demos::Demonstration>& demos, const std::string& object = "box",
                      const std::string& robot = "")
{
  vrrw_skills::LearnOptions options;
  options.object = object;
  options.robot = robot;
  try
  {
    vrrw_skills::learnSkill(demos, options);
  }
  catch (const vrrw_skills::SkillError& e)
  {
    return e.what();
  }
  return "no refusal";
}
}  // namespace

TEST(SkillLearning, KeyframesComeOutOfTheDemonstrationInTheirFrames)
{
  vrrw_skills::LearnOptions options;
  options.object = "box";
  const vrrw_skills::Skill skill = vrrw_skills::learnSkill({ vrrw_skills_test::xyzPickPlace() }, options);
  std::vector<std::string> names;
  for (const auto& instruction : skill.instructions)
    names.push_back(instruction.name);
  EXPECT_EQ(names, (std::vector<std::string>{ "near_pick", "pick", "close_gripper", "back_to_near_pick", "final",
                                              "open_gripper" }));
  // taken 15 cm above the box's centre, from 12 cm above that, lifted as much, set down at (0.4, -0.2)
  const auto expect = [](const vrrw_skills::Keyframe& k, vrrw_skills::Frame frame, const Eigen::Vector3d& at) {
    EXPECT_EQ(k.frame, frame);
    EXPECT_LT((k.pose.position - at).norm(), 1e-5) << k.pose.position.transpose();  // measured 1-7 um
  };
  expect(skill.grasp(), vrrw_skills::Frame::object, { 0.0, 0.0, 0.15 });
  expect(skill.instruction("near_pick")->end, vrrw_skills::Frame::object, { 0.0, 0.0, 0.27 });
  expect(skill.instruction("back_to_near_pick")->end, vrrw_skills::Frame::object, { 0.0, 0.0, 0.27 });
  expect(skill.instruction("final")->end, vrrw_skills::Frame::world, { 0.4, -0.2, 0.95 });
  EXPECT_LT((skill.object_in_hand.position - Eigen::Vector3d(0, 0, -0.15)).norm(), 1e-6);
  EXPECT_LT((skill.object_start.position - Eigen::Vector3d(0.4, 0.1, 0.8)).norm(), 1e-9);
  EXPECT_LT((skill.object_end.position - Eigen::Vector3d(0.4, -0.2, 0.8)).norm(), 1e-9);
  const auto* close = skill.instruction("close_gripper");
  EXPECT_EQ(close->gripper_position, 0.8);
  EXPECT_EQ(close->gripper_effort, 40.0);
  EXPECT_NEAR(close->gripper_reached, 0.5, 1e-9);
  // the carry's rest above the place (0.5 s, 0.7 s between the motions' walked-out ends) is cut to 0.5 s
  EXPECT_NEAR(skill.instruction("final")->joint_dmp->demoDuration(), 3.3, 0.1);
  EXPECT_LT(skill.instruction("final")->cartesian_fit_rmse, 2e-3);
  ASSERT_EQ(skill.sources.size(), 1u);
  EXPECT_EQ(skill.sources[0].bag, "xyz.bag");
  EXPECT_EQ(skill.sources[0].scene, "xyz_cell");
  EXPECT_EQ(skill.sources[0].segments.size(), 6u);
  EXPECT_EQ(skill.robot, "bot");
  EXPECT_EQ(skill.tcp_link, "bot_tcp");
}

TEST(SkillLearning, DemonstrationsThatDoNotShowTheTaskAreRefused)
{
  auto never_closed = vrrw_skills_test::xyzPickPlace();
  never_closed.robots[0].gripper_goals.clear();
  for (auto& state : never_closed.robots[0].states)
    state.gripper = 0.0;
  EXPECT_EQ(refusalOf({ never_closed }).rfind("xyz.bag: robot 'bot': the gripper never closed", 0), 0u)
      << refusalOf({ never_closed });
  auto never_opened = vrrw_skills_test::xyzPickPlace();
  never_opened.robots[0].gripper_goals.pop_back();
  for (auto& state : never_opened.robots[0].states)
    state.gripper = std::max(state.gripper, state.time > 5.0 ? 0.5 : 0.0);
  EXPECT_EQ(refusalOf({ never_opened }).rfind("xyz.bag: robot 'bot': the gripper never opened after it closed", 0), 0u)
      << refusalOf({ never_opened });
  auto no_robot = vrrw_skills_test::xyzPickPlace();
  no_robot.robots.clear();
  EXPECT_EQ(refusalOf({ no_robot }), "xyz.bag: joint_states: no robot's joint states recorded (a bag of `./vrrw "
                                     "record` or /demos/start has them)");
  auto unmoved = vrrw_skills_test::xyzPickPlace();
  for (auto& pose : unmoved.objects["box"])
    pose.pose = unmoved.objects["box"].front().pose;
  EXPECT_EQ(refusalOf({ unmoved }), "xyz.bag: /tf: object 'box' never moved (0.00 mm from the start to the end of "
                                    "the recording)");
  EXPECT_EQ(refusalOf({ vrrw_skills_test::xyzPickPlace() }, "crate"),
            "xyz.bag: /tf: no pose of object 'crate' (objects in the bag: box, table)");
  EXPECT_EQ(refusalOf({ vrrw_skills_test::xyzPickPlace() }, "box", "ur5e"),
            "xyz.bag: --robot ur5e: no joint_states of that robot (the bag has: bot)");
  auto other_robot = vrrw_skills_test::xyzPickPlace("other.bag");
  other_robot.robots[0].robot = "bot2";
  other_robot.metadata.robots["bot2"].tcp_link = "bot_tcp";
  const std::string mixed = refusalOf({ vrrw_skills_test::xyzPickPlace(), other_robot });
  EXPECT_EQ(mixed.rfind("other.bag: robot 'bot2' (joints bot_x_joint, bot_y_joint, bot_z_joint) is not the robot of "
                        "xyz.bag",
                        0),
            0u)
      << mixed;
  auto other_object = vrrw_skills_test::xyzPickPlace("other.bag");
  other_object.objects["crate"] = other_object.objects["box"];
  other_object.objects.erase("box");
  EXPECT_EQ(refusalOf({ vrrw_skills_test::xyzPickPlace(), other_object }),
            "other.bag: /tf: no pose of object 'box' (objects in the bag: crate, table)");
  EXPECT_EQ(refusalOf({}), "skill learn: no demonstration given");
}

TEST(SkillLearning, SeveralDemonstrationsAverageTheKeyframes)
{
  auto lower = vrrw_skills_test::xyzPickPlace("lower.bag");
  for (auto& pose : lower.objects["box"])
    pose.pose.position[2] += 0.004;  // the box 4 mm higher in the hand: the grasp 4 mm lower on it
  vrrw_skills::LearnOptions options;
  options.object = "box";
  const auto skill = vrrw_skills::learnSkill({ vrrw_skills_test::xyzPickPlace(), lower }, options);
  EXPECT_LT((skill.grasp().pose.position - Eigen::Vector3d(0, 0, 0.148)).norm(), 1e-5);
  EXPECT_EQ(skill.sources.size(), 2u);
}
