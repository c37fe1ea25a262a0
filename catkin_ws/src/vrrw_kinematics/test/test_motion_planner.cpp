#include <fcl/narrowphase/collision.h>
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "fixtures.h"
#include "scene_fixtures.h"
#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/motion_planner.h"
#include "vrrw_kinematics/time_parameterization.h"

using namespace vrrw_kinematics;

namespace
{
const std::vector<std::string> kJoints = { "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                           "wrist_1_joint", "wrist_2_joint", "wrist_3_joint" };

/// Deepest (m) any pair the world checks goes into the other at q, from FCL's contacts; `self` tells
/// whether that pair is two links of the robot.
double deepestPenetration(const CollisionWorld& world, const Eigen::VectorXd& q, bool& self)
{
  std::vector<Eigen::Isometry3d> poses;
  world.bodyTransforms(q, poses);
  const fcl::CollisionRequestd request(1, true);
  double deepest = 0.0;
  for (const auto& pair : world.checkedPairs())
  {
    const CollisionElement& a = world.elements()[pair.first];
    const CollisionElement& b = world.elements()[pair.second];
    fcl::CollisionResultd result;
    fcl::collide(a.geometry.get(), poses[a.body] * a.local, b.geometry.get(), poses[b.body] * b.local, request,
                 result);
    if (!result.isCollision() || result.getContact(0).penetration_depth <= deepest)
      continue;
    deepest = result.getContact(0).penetration_depth;
    self = world.bodies()[a.body].link >= 0 && world.bodies()[b.body].link >= 0;
  }
  return deepest;
}

class MotionPlannerTest : public ::testing::Test
{
protected:
  MotionPlannerTest()
    : world_(fixture("ur5e.urdf"), { slab("floor", Eigen::Vector3d(0, 0, -0.04), Eigen::Vector3d(3, 3, 0.1)),
                                     slab("pillar", Eigen::Vector3d(0.55, 0, 0.35), Eigen::Vector3d(0.2, 0.2, 0.7)) })
  {
    world_.computeAllowedCollisions(1000, 1);
    planner_ = std::make_unique<MotionPlanner>(world_, kJoints, "tool0", Eigen::VectorXd::Zero(6));
  }

  /// Independent re-check of the motion between the planner's checked states with the full-world checker,
  /// 16 states per step: a state may graze only as deep as the planner's resolution allows (SegmentChecker:
  /// half a step past a face, a step at an edge, twice that between two links of the arm).
  void expectPathCollisionFree(const std::vector<Eigen::VectorXd>& path)
  {
    EXPECT_GE(path.size(), 2u);
    for (std::size_t i = 1; i < path.size(); ++i)
    {
      const std::size_t steps = 16 * planner_->segmentSteps(path[i - 1], path[i]);
      for (std::size_t s = 0; s <= steps; ++s)
      {
        const Eigen::VectorXd q = path[i - 1] + (path[i] - path[i - 1]) * (static_cast<double>(s) / steps);
        EXPECT_TRUE((q.array() >= planner_->lowerLimits().array() - 1e-9).all());
        EXPECT_TRUE((q.array() <= planner_->upperLimits().array() + 1e-9).all());
        if (s % 16 == 0)
        {
          EXPECT_TRUE(planner_->stateValid(q)) << "segment " << i << " checked step " << s / 16;
        }
        const Contact contact = world_.check(q);
        if (!contact.collision)
          continue;
        bool self = false;
        const double depth = deepestPenetration(world_, q, self);
        EXPECT_LE(depth, (self ? 2.0 : 1.0) * planner_->resolution())
            << "segment " << i << " step " << s << ": " << contact.body_a << " - " << contact.body_b;
      }
    }
  }

  CollisionWorld world_;
  std::unique_ptr<MotionPlanner> planner_;
  const Eigen::VectorXd start_ = vec({ -1.2, -1.2, 1.2, -1.57, -1.57, 0.0 });
  const Eigen::VectorXd goal_ = vec({ 1.2, -1.2, 1.2, -1.57, -1.57, 0.0 });
};
}  // namespace

TEST_F(MotionPlannerTest, JointGoalAroundAnObstacle)
{
  ASSERT_TRUE(planner_->stateValid(start_));
  ASSERT_TRUE(planner_->stateValid(goal_));
  EXPECT_FALSE(planner_->segmentValid(start_, goal_));
  PlanRequest request;
  request.start = start_;
  request.goal_joints = goal_;
  request.time_limit = 2.0;
  const PlanResult result = planner_->plan(request);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LT((result.path.front() - start_).norm(), 1e-12);
  EXPECT_LT((result.path.back() - goal_).norm(), 1e-12);
  EXPECT_GE(result.path.size(), 3u);
  EXPECT_NEAR(result.path_length, pathLength(result.path), 1e-12);
  EXPECT_GT(result.path_length, (goal_ - start_).norm());
  expectPathCollisionFree(result.path);
}

TEST_F(MotionPlannerTest, TimedTrajectoryFollowsTheCheckedPath)
{
  PlanRequest request;
  request.start = start_;
  request.goal_joints = goal_;
  const PlanResult result = planner_->plan(request);
  ASSERT_TRUE(result.success) << result.message;
  TimingOptions timing;
  timing.max_velocity.assign(6, M_PI);
  timing.max_acceleration.assign(6, M_PI);
  timing.max_deviation = 0.0;
  const auto exact = TimeParameterization(timing).compute(result.path, kJoints);
  EXPECT_TRUE(planner_->trajectoryValid(exact));
  EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(exact.points.back().positions.data(), 6) - goal_).norm(), 1e-12);
  vrrw_trajectory::JointTrajectory outside = exact;
  outside.points[outside.points.size() / 2].positions[2] = 4.0;
  EXPECT_FALSE(planner_->trajectoryValid(outside));
}

TEST_F(MotionPlannerTest, SameSeedSamePath)
{
  for (const bool simplify : { false, true })
  {
    PlanRequest request;
    request.start = start_;
    request.goal_joints = goal_;
    request.seed = 42;
    request.simplify = simplify;
    request.shortcut_attempts = simplify ? 20 : 0;
    const PlanResult first = planner_->plan(request);
    const PlanResult second = planner_->plan(request);
    ASSERT_TRUE(first.success && second.success);
    ASSERT_EQ(first.path.size(), second.path.size()) << "simplify " << simplify;
    for (std::size_t i = 0; i < first.path.size(); ++i)
      EXPECT_LT((first.path[i] - second.path[i]).norm(), 1e-12) << "simplify " << simplify;
  }
}

TEST_F(MotionPlannerTest, PoseGoalThroughIk)
{
  const Eigen::Isometry3d target = planner_->ik().chain().fk(goal_);
  PlanRequest request;
  request.start = start_;
  request.goal_pose = planner_->chainBasePose() * target;
  request.time_limit = 2.0;
  const PlanResult result = planner_->plan(request);
  ASSERT_TRUE(result.success) << result.message;
  const Eigen::Isometry3d reached = planner_->ik().chain().fk(result.path.back());
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-5);
  EXPECT_LT(rotationError(target.linear(), reached.linear()).norm(), 1e-5);
  expectPathCollisionFree(result.path);
}

TEST_F(MotionPlannerTest, OtherPlannersByName)
{
  for (const std::string name : { "RRT", "PRM", "BiTRRT", "KPIECE1" })
  {
    PlanRequest request;
    request.start = start_;
    request.goal_joints = goal_;
    request.planner = name;
    request.time_limit = 2.0;
    const PlanResult result = planner_->plan(request);
    ASSERT_TRUE(result.success) << name << ": " << result.message;
    expectPathCollisionFree(result.path);
  }
}

// Random motions among thin rods, checked at a coarse resolution (10 cm) so that grazes between the checked
// states are common enough to see: an accepted motion grazes a rod no deeper than the resolution allows.
TEST(SegmentCheck, GrazesBetweenCheckedStatesStayWithinTheResolution)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<vrrw_scene::Object> rods;
  while (rods.size() < 16)
  {
    const Eigen::Vector3d at(0.9 * unit(rng), 0.9 * unit(rng), 0.5);
    if (at.head<2>().norm() > 0.3 && at.head<2>().norm() < 0.9)
      rods.push_back(slab("rod" + std::to_string(rods.size()), at, Eigen::Vector3d(0.008, 0.008, 1.0)));
  }
  CollisionWorld world(fixture("ur5e.urdf"), rods);
  world.computeAllowedCollisions(1000, 1);
  MotionPlanner planner(world, kJoints, "tool0", Eigen::VectorXd::Zero(6), 0.1);
  int tried = 0, accepted = 0, grazing = 0;
  double deepest_graze = 0.0;
  while (tried < 1000)
  {
    Eigen::VectorXd a(6), b(6);
    for (int j = 0; j < 6; ++j)
    {
      a[j] = (j == 1 ? -1.57 : 0.0) + (j < 3 ? 1.5 : 3.0) * unit(rng);
      b[j] = a[j] + 1.0 * unit(rng);
    }
    if (!planner.stateValid(a) || !planner.stateValid(b))
      continue;
    ++tried;
    if (!planner.segmentValid(a, b))
      continue;
    ++accepted;
    const std::size_t steps = 16 * planner.segmentSteps(a, b);
    double deepest = 0.0;
    bool self = false;
    for (std::size_t s = 0; s <= steps; ++s)
    {
      const Eigen::VectorXd q = a + (b - a) * (static_cast<double>(s) / steps);
      if (world.check(q).collision)
        deepest = std::max(deepest, deepestPenetration(world, q, self));
    }
    EXPECT_LE(deepest, (self ? 2.0 : 1.0) * planner.resolution()) << "motion " << tried;
    grazing += deepest > 0.0;
    deepest_graze = std::max(deepest_graze, deepest);
  }
  EXPECT_GT(grazing, 0) << "no accepted motion grazes a rod: the bound is not exercised";
  std::printf("%d motions, %d accepted, %d of them graze a rod between checked states (deepest %.2g m at a "
              "resolution of %.2g m)\n",
              tried, accepted, grazing, deepest_graze, planner.resolution());
}

TEST_F(MotionPlannerTest, BadRequestsGiveCodes)
{
  PlanRequest request;
  request.start = start_;
  request.goal_joints = goal_;
  request.planner = "NoSuchPlanner";
  EXPECT_EQ(planner_->plan(request).code, ErrorCode::InvalidArgument);

  request.planner = "RRTConnect";
  request.goal_joints = vec({ 0, 0, 4.0, 0, 0, 0 });
  PlanResult result = planner_->plan(request);
  EXPECT_EQ(result.code, ErrorCode::OutsideLimits);
  EXPECT_NE(result.message.find("elbow_joint"), std::string::npos);

  request.goal_joints = vec({ 0.0, -0.3, 0.0, 0.0, 0.0, 0.0 });  // reaching into the pillar
  result = planner_->plan(request);
  EXPECT_EQ(result.code, ErrorCode::InCollision);
  EXPECT_NE(result.message.find("pillar"), std::string::npos);

  request.start = vec({ 0.0, -0.3, 0.0, 0.0, 0.0, 0.0 });
  request.goal_joints = goal_;
  EXPECT_EQ(planner_->plan(request).code, ErrorCode::InCollision);

  request.start = start_;
  request.goal_joints.reset();
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 3.0, 0.0, 0.5;
  request.goal_pose = far;
  EXPECT_EQ(planner_->plan(request).code, ErrorCode::NoSolution);
  far.translation().x() = std::nan("");
  request.goal_pose = far;
  EXPECT_EQ(planner_->plan(request).code, ErrorCode::InvalidPose);

  request.goal_pose.reset();
  EXPECT_EQ(planner_->plan(request).code, ErrorCode::InvalidArgument);
  EXPECT_THROW(MotionPlanner(world_, kJoints, "shoulder_link", Eigen::VectorXd::Zero(6)), KinematicsError);
}
