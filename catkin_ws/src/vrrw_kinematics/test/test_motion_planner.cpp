#include <gtest/gtest.h>

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

  /// Independent re-check with the full-world checker, at twice the planner's step count.
  void expectPathCollisionFree(const std::vector<Eigen::VectorXd>& path)
  {
    ASSERT_GE(path.size(), 2u);
    for (std::size_t i = 1; i < path.size(); ++i)
    {
      const std::size_t steps = 2 * planner_->segmentSteps(path[i - 1], path[i]);
      for (std::size_t s = 0; s <= steps; ++s)
      {
        const Eigen::VectorXd q = path[i - 1] + (path[i] - path[i - 1]) * (static_cast<double>(s) / steps);
        const Contact contact = world_.check(q);
        ASSERT_FALSE(contact.collision) << "segment " << i << " step " << s << ": " << contact.body_a << " - "
                                        << contact.body_b;
        ASSERT_TRUE((q.array() >= planner_->lowerLimits().array() - 1e-9).all());
        ASSERT_TRUE((q.array() <= planner_->upperLimits().array() + 1e-9).all());
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
