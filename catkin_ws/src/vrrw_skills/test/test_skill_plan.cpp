#include <gtest/gtest.h>

#include <cmath>

#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_plan.h>

#include "skill_fixture.h"

using vrrw_skills::CartesianPose;
using vrrw_skills::ContactPair;
using vrrw_skills::SkillPlanner;
using vrrw_skills::SkillRefusal;
using vrrw_skills::SkillScene;
using vrrw_skills_test::jointsOf;
using vrrw_skills_test::poseOf;

namespace
{
SkillScene sceneWith(const vrrw_skills::Skill& skill, const CartesianPose& object)
{
  SkillScene scene;
  scene.robot = skill.robot;
  scene.arm_joints = skill.arm_joints;
  scene.joints = skill.joints_home;
  scene.max_velocity.assign(6, 2.0);
  scene.max_acceleration.assign(6, 100.0);
  scene.object = object;
  return scene;
}

CartesianPose movedObject(const vrrw_skills::Skill& skill, double dx, double dy, double yaw)
{
  CartesianPose object = skill.object_start;
  object.position += Eigen::Vector3d(dx, dy, 0.0);
  object.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())) * object.orientation;
  return object;
}

std::string refusalOf(const std::function<void()>& action)
{
  try
  {
    action();
  }
  catch (const SkillRefusal& e)
  {
    return e.what();
  }
  return "no refusal";
}
}  // namespace

TEST(SkillPlan, GoalsFollowTheObjectAndThePlaceStays)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  const auto object = movedObject(skill, 0.08, -0.05, 0.4);
  const auto goals = vrrw_skills::goalPoses(skill, sceneWith(skill, object), skill.object_in_hand);
  // the grasp sits on the object as demonstrated: 20 cm above its base, turned with it
  const CartesianPose grasp = goals.at("pick");
  EXPECT_NEAR((grasp.position - (object.position + Eigen::Vector3d(0, 0, 0.2))).norm(), 0.0, 1e-12);
  EXPECT_NEAR(vrrw_skills::angleDistance(grasp, vrrw_skills_test::pose(0, 0, 0, 0.4)), 0.0, 1e-12);
  EXPECT_NEAR(goals.at("near_pick").position.z() - grasp.position.z(), 0.12, 1e-12);
  // held as demonstrated, the object is released where the demonstration left it
  EXPECT_NEAR((goals.at("final").position - Eigen::Vector3d(0.4, -0.2, 0.95)).norm(), 0.0, 1e-12);
  // held 1 cm lower in the hand: the TCP goes 1 cm higher to put it there
  CartesianPose lower = skill.object_in_hand;
  lower.position.z() += 0.01;  // the tool's z points down
  const auto corrected = vrrw_skills::goalPoses(skill, sceneWith(skill, object), lower);
  EXPECT_NEAR(corrected.at("final").position.z() - 0.95, 0.01, 1e-12);
}

TEST(SkillPlan, TheTaughtArmRollsOutJointDmpsToIkGoalsAndEndsAtThemAtRest)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  SkillPlanner planner(skill, arm);
  auto scene = sceneWith(skill, movedObject(skill, -0.06, 0.07, -0.3));
  ASSERT_TRUE(planner.taughtArm(scene));
  const auto approach = planner.approach(scene);
  ASSERT_EQ(approach.size(), 3u);
  EXPECT_EQ(approach[0].instruction, "near_pick");
  EXPECT_EQ(approach[2].instruction, "close_gripper");
  EXPECT_EQ(approach[2].gripper_position, 0.8);
  EXPECT_EQ(approach[2].gripper_effort, 70.0);
  for (int s = 0; s < 2; ++s)
  {
    const auto& motion = approach[s].trajectory;
    EXPECT_EQ(motion.points.front().positions, s == 0 ? scene.joints : planner.goals().at("near_pick"));
    EXPECT_EQ(motion.points.back().positions, planner.goals().at(approach[s].instruction));
    for (double v : motion.points.back().velocities)
      EXPECT_EQ(v, 0.0);
    // no creeping: ends within 0.25 s of the demonstrated duration, or as much later as the limits asked
    EXPECT_LE(motion.duration(), skill.instruction(approach[s].instruction)->joint_dmp->demoDuration() * 1.2 + 0.25);
  }
  scene.joints = planner.goals().at("pick");
  const auto carry = planner.carry(scene, skill.object_in_hand);
  ASSERT_EQ(carry.size(), 3u);
  EXPECT_EQ(carry[1].instruction, "final");
  EXPECT_NEAR((poseOf(carry[1].trajectory.points.back().positions).position - Eigen::Vector3d(0.4, -0.2, 0.95)).norm(),
              0.0, 1e-9);
  EXPECT_EQ(carry[2].instruction, "open_gripper");
  // only the set-down ends pressed onto the support: its goal accepts that contact, every other the controller's
  EXPECT_EQ(carry[1].goal_tolerance, SkillPlanner::kSetDownTolerance);
  for (const auto* step : { &approach[0], &approach[1], &carry[0] })
    EXPECT_EQ(step->goal_tolerance, 0.0) << step->instruction;
}

TEST(SkillPlan, AnotherArmFollowsTheCartesianDmpByIk)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  SkillPlanner planner(skill, arm);
  auto scene = sceneWith(skill, movedObject(skill, 0.05, 0.05, 0.2));
  scene.robot = "other";
  ASSERT_FALSE(planner.taughtArm(scene));
  const auto approach = planner.approach(scene);
  const auto& pick = approach[1].trajectory;
  // the TCP goes straight down onto the object as demonstrated: every point of the path by IK of the
  // Cartesian rollout stays within 1 mm of the vertical through the grasp
  const Eigen::Vector3d grasp = poseOf(pick.points.back().positions).position;
  for (const auto& point : pick.points)
    EXPECT_LT((poseOf(point.positions).position - grasp).head<2>().norm(), 1e-3);
  EXPECT_GT(arm.ik_calls, 20);  // one IK per 50 ms of the path
}

TEST(SkillPlan, AnUnreachableGoalIsRefusedBeforeAnythingMoves)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  arm.reach = 1.2;  // the near-pick pose (1.15 m from the origin) is in, the grasp above a far object is not
  SkillPlanner planner(skill, arm);
  const std::string refusal = refusalOf([&] { planner.approach(sceneWith(skill, movedObject(skill, 0.6, 0.4, 0.0))); });
  EXPECT_EQ(refusal.rfind("near_pick: no IK for its goal: out of reach (", 0), 0u) << refusal;
}

TEST(SkillPlan, CollisionsAreRefusedExceptTheFingersAtTheGraspAndTheObjectOnItsSupport)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  SkillPlanner planner(skill, arm);
  auto scene = sceneWith(skill, skill.object_start);
  // the fingers touch the box in the last 2 cm above the grasp: allowed
  arm.touches = [](const std::vector<double>& q) {
    return q[2] < 0.97 ? ContactPair{ "toy_left_inner_finger", "box" } : ContactPair{};
  };
  EXPECT_NO_THROW(planner.approach(scene));
  // the wrist touching the table on the way down is not, nor at the grasp
  arm.touches = [](const std::vector<double>& q) {
    return q[2] < 1.03 && q[2] > 1.0 ? ContactPair{ "toy_wrist_3_link", "table" } : ContactPair{};
  };
  const std::string wrist = refusalOf([&] { planner.approach(scene); });
  EXPECT_EQ(wrist.rfind("pick: collision on the way: toy_wrist_3_link would touch table at ", 0), 0u) << wrist;
  arm.touches = [](const std::vector<double>& q) {
    return q[2] < 0.96 ? ContactPair{ "toy_wrist_3_link", "table" } : ContactPair{};
  };
  EXPECT_EQ(refusalOf([&] { planner.approach(scene); }),
            "pick: no IK for its goal: collision (toy_wrist_3_link - table)");
  // held, the box may touch the table where it stood and where it is set down, not on the way
  arm.touches = [](const std::vector<double>&) { return ContactPair{}; };
  planner.approach(sceneWith(skill, skill.object_start));
  scene.joints = jointsOf(vrrw_skills_test::pose(0.4, 0.1, 0.95));
  arm.touches = [](const std::vector<double>& q) {
    return q[2] < 0.955 ? ContactPair{ "box", "table" } : ContactPair{};
  };
  EXPECT_NO_THROW(planner.carry(scene, skill.object_in_hand));
  arm.touches = [](const std::vector<double>& q) {
    return q[1] < 0.0 && q[1] > -0.1 ? ContactPair{ "box", "bin" } : ContactPair{};
  };
  const std::string carried = refusalOf([&] { planner.carry(scene, skill.object_in_hand); });
  EXPECT_EQ(carried.rfind("final: collision on the way: box would touch bin at ", 0), 0u) << carried;
}

TEST(SkillPlan, APieceIsCheckedInOneCallEveryCheckStep)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  SkillPlanner planner(skill, arm);
  std::vector<std::vector<double>> checked;
  arm.touches = [&checked](const std::vector<double>& q) {
    checked.push_back(q);
    return ContactPair{};
  };
  const auto steps = planner.approach(sceneWith(skill, skill.object_start));
  // one call per goal that may touch the object (pick, back_to_near_pick, final: all solved before anything
  // moves) and one per arm piece: not one per state
  std::size_t pieces = 0;
  for (const auto& step : steps)
    pieces += step.trajectory.points.empty() ? 0 : 1;
  EXPECT_EQ(static_cast<std::size_t>(arm.path_checks), pieces + 3);
  EXPECT_GT(checked.size(), 3 * pieces);
  // consecutive checked states of a piece are at most a check step (and one sample) apart
  double largest_gap = 0.0;
  for (std::size_t k = 1; k < checked.size(); ++k)
  {
    double gap = 0.0;
    for (std::size_t j = 0; j < checked[k].size(); ++j)
      gap = std::max(gap, std::abs(checked[k][j] - checked[k - 1][j]));
    if (gap < 0.1)  // within a piece (pieces start where the last one ended, the goal check is elsewhere)
      largest_gap = std::max(largest_gap, gap);
  }
  EXPECT_LT(largest_gap, 2 * SkillPlanner::kCheckStep);
}

TEST(SkillPlan, AJointRolloutThatCollidesFollowsTheCartesianDmpInstead)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  SkillPlanner planner(skill, arm);
  planner.approach(sceneWith(skill, skill.object_start));
  auto scene = sceneWith(skill, skill.object_start);
  scene.joints = jointsOf(vrrw_skills_test::pose(0.4, 0.1, 0.95));
  // the held box passes the bin only on the joint rollouts (no IK between their goals; carry() solves one, the
  // place's goal again): the Cartesian path, an IK per 50 ms, stands for the path that keeps its height
  const int solved = arm.ik_calls + 1;
  arm.touches = [&arm, solved](const std::vector<double>& q) {
    return arm.ik_calls <= solved && q[1] < 0.0 && q[1] > -0.1 ? ContactPair{ "box", "bin" } : ContactPair{};
  };
  const auto carry = planner.carry(scene, skill.object_in_hand);
  ASSERT_EQ(carry.size(), 3u);
  EXPECT_FALSE(carry[0].cartesian);  // back_to_near_pick never comes near the bin
  EXPECT_TRUE(carry[1].cartesian);
  EXPECT_GT(arm.ik_calls, solved + 20);
  EXPECT_EQ(carry[1].trajectory.points.front().positions, planner.goals().at("back_to_near_pick"));
  EXPECT_EQ(carry[1].trajectory.points.back().positions, planner.goals().at("final"));
  // in the way of both: refused, with both reasons
  arm.touches = [](const std::vector<double>& q) {
    return q[1] < 0.0 && q[1] > -0.1 ? ContactPair{ "box", "bin" } : ContactPair{};
  };
  const std::string both = refusalOf([&] { planner.carry(scene, skill.object_in_hand); });
  EXPECT_EQ(both.rfind("final: collision on the way: box would touch bin at ", 0), 0u) << both;
  EXPECT_NE(both.find(" (along the Cartesian DMP too: collision on the way: box would touch bin at "),
            std::string::npos)
      << both;
}

TEST(SkillPlan, AMotionOverTheLimitsIsSlowedDownAsAWhole)
{
  const auto skill = vrrw_skills_test::pickAndPlace();
  vrrw_skills_test::ToyArm arm;
  SkillPlanner planner(skill, arm);
  auto scene = sceneWith(skill, skill.object_start);
  const double free_duration = planner.approach(scene)[0].trajectory.duration();
  scene.max_velocity.assign(6, 0.05);
  const auto slow = planner.approach(scene)[0].trajectory;
  EXPECT_GT(slow.duration(), 2.0 * free_duration);
  double fastest = 0.0;
  for (const auto& point : slow.points)
    for (double v : point.velocities)
      fastest = std::max(fastest, std::abs(v));
  EXPECT_LE(fastest, 0.05 * SkillPlanner::kVelocityMargin * 1.01);  // sampled at other phases of the rollout
}
