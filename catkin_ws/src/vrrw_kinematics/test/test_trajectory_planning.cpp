// planTrajectory: start -> joint-space waypoints -> goal around a pillar, on the UR5e test URDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include <vrrw_kinematics/trajectory_planning.h>

#include "fixtures.h"
#include "scene_fixtures.h"

using namespace vrrw_kinematics;

namespace
{
const std::vector<std::string> kJoints = { "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                           "wrist_1_joint", "wrist_2_joint", "wrist_3_joint" };

Eigen::VectorXd positions(const vrrw_trajectory::TrajectoryPoint& point)
{
  return Eigen::Map<const Eigen::VectorXd>(point.positions.data(), static_cast<Eigen::Index>(point.positions.size()));
}

class TrajectoryPlanningTest : public ::testing::Test
{
protected:
  TrajectoryPlanningTest()
    : world_(fixture("ur5e.urdf"), { slab("floor", Eigen::Vector3d(0, 0, -0.04), Eigen::Vector3d(3, 3, 0.1)),
                                     slab("pillar", Eigen::Vector3d(0.55, 0, 0.35), Eigen::Vector3d(0.2, 0.2, 0.7)) })
  {
    world_.computeAllowedCollisions(1000, 1);
    planner_ = std::make_unique<MotionPlanner>(world_, kJoints, "tool0", Eigen::VectorXd::Zero(6));
    timing_.max_velocity.assign(6, M_PI);
    timing_.max_acceleration.assign(6, M_PI);
    request_.plan.start = vec({ -1.2, -1.2, 1.2, -1.57, -1.57, 0.0 });
    request_.plan.goal_joints = vec({ 1.2, -1.2, 1.2, -1.57, -1.57, 0.0 });
    request_.plan.time_limit = 5.0;
    request_.waypoints = { vec({ -0.6, -1.9, 1.6, -1.2, -1.57, 0.4 }), vec({ 0.6, -1.7, 1.0, -1.57, -1.2, -0.4 }) };
  }

  /// Every motion between consecutive samples is free: re-checked with the full-world checker.
  void expectCollisionFree(const vrrw_trajectory::JointTrajectory& trajectory)
  {
    for (std::size_t k = 1; k < trajectory.points.size(); ++k)
    {
      const Eigen::VectorXd a = positions(trajectory.points[k - 1]), b = positions(trajectory.points[k]);
      const std::size_t steps = 2 * planner_->segmentSteps(a, b);
      for (std::size_t s = 0; s <= steps; ++s)
      {
        const Contact contact = world_.check(a + (b - a) * (static_cast<double>(s) / static_cast<double>(steps)));
        ASSERT_FALSE(contact.collision) << "point " << k << ": " << contact.body_a << " - " << contact.body_b;
      }
    }
  }

  CollisionWorld world_;
  std::unique_ptr<MotionPlanner> planner_;
  TimingOptions timing_;
  TrajectoryRequest request_;
};
}  // namespace

TEST_F(TrajectoryPlanningTest, PassesThroughEveryWaypointAtRest)
{
  for (const Eigen::VectorXd& waypoint : request_.waypoints)
    ASSERT_TRUE(planner_->stateValid(waypoint));
  const TrajectoryResult result = planTrajectory(*planner_, timing_, request_);
  ASSERT_TRUE(result.success) << result.message;
  ASSERT_EQ(result.waypoint_times.size(), 3u);
  const auto& points = result.trajectory.points;
  EXPECT_EQ(result.trajectory.joint_names, kJoints);
  EXPECT_LT((positions(points.front()) - request_.plan.start).cwiseAbs().maxCoeff(), 1e-12);
  std::vector<Eigen::VectorXd> stops = request_.waypoints;
  stops.push_back(*request_.plan.goal_joints);
  for (std::size_t w = 0; w < stops.size(); ++w)
  {
    const auto at = std::find_if(points.begin(), points.end(), [&](const auto& p) { return p.time == result.waypoint_times[w]; });
    ASSERT_NE(at, points.end()) << "no point at the time of waypoint " << w;
    EXPECT_LT((positions(*at) - stops[w]).cwiseAbs().maxCoeff(), 1e-6) << "waypoint " << w;
    for (const double v : at->velocities)
      EXPECT_EQ(v, 0.0) << "waypoint " << w;
  }
  EXPECT_LT(result.waypoint_times[0], result.waypoint_times[1]);
  EXPECT_EQ(result.waypoint_times[2], points.back().time);
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    ASSERT_GT(points[k].time, points[k - 1].time) << k;
    for (std::size_t i = 0; i < 6; ++i)
      EXPECT_LE(std::abs(points[k].velocities[i]), M_PI * (1 + 1e-9)) << k;
  }
  EXPECT_GT(result.path_length, (stops[0] - request_.plan.start).norm() + (stops[1] - stops[0]).norm());
  EXPECT_LT((result.path.front() - request_.plan.start).norm(), 1e-12);
  EXPECT_LT((result.path.back() - stops.back()).norm(), 1e-12);
  expectCollisionFree(result.trajectory);
}

TEST_F(TrajectoryPlanningTest, WithoutWaypointsItIsOnePlannedLeg)
{
  request_.waypoints.clear();
  const TrajectoryResult result = planTrajectory(*planner_, timing_, request_);
  ASSERT_TRUE(result.success) << result.message;
  ASSERT_EQ(result.waypoint_times.size(), 1u);
  EXPECT_LT((positions(result.trajectory.points.back()) - *request_.plan.goal_joints).norm(), 1e-12);
  expectCollisionFree(result.trajectory);
}

TEST_F(TrajectoryPlanningTest, PoseGoalAfterTheWaypoints)
{
  const Eigen::Isometry3d target = planner_->ik().chain().fk(*request_.plan.goal_joints);
  request_.plan.goal_joints.reset();
  request_.plan.goal_pose = planner_->chainBasePose() * target;
  const TrajectoryResult result = planTrajectory(*planner_, timing_, request_);
  ASSERT_TRUE(result.success) << result.message;
  const Eigen::Isometry3d reached = planner_->ik().chain().fk(positions(result.trajectory.points.back()));
  EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-5);
  EXPECT_LT(rotationError(target.linear(), reached.linear()).norm(), 1e-5);
  EXPECT_LT((positions(result.trajectory.points.front()) - request_.plan.start).norm(), 1e-12);
}

TEST_F(TrajectoryPlanningTest, NamesTheWaypointThatFails)
{
  TrajectoryRequest in_pillar = request_;
  in_pillar.waypoints[1] = vec({ 0.0, -0.3, 0.0, 0.0, 0.0, 0.0 });  // reaching into the pillar
  TrajectoryResult result = planTrajectory(*planner_, timing_, in_pillar);
  EXPECT_EQ(result.code, ErrorCode::InCollision);
  EXPECT_EQ(result.failed_waypoint, 1);
  EXPECT_TRUE(result.contact.body_a == "pillar" || result.contact.body_b == "pillar");
  EXPECT_EQ(result.message.rfind("waypoint 1: in collision (", 0), 0u) << result.message;
  EXPECT_TRUE(result.trajectory.points.empty());

  TrajectoryRequest outside = request_;
  outside.waypoints[0][2] = 4.0;
  result = planTrajectory(*planner_, timing_, outside);
  EXPECT_EQ(result.code, ErrorCode::OutsideLimits);
  EXPECT_EQ(result.failed_waypoint, 0);
  EXPECT_NE(result.message.find("elbow_joint"), std::string::npos) << result.message;

  TrajectoryRequest short_waypoint = request_;
  short_waypoint.waypoints[1] = vec({ 0.0, -1.5 });
  result = planTrajectory(*planner_, timing_, short_waypoint);
  EXPECT_EQ(result.code, ErrorCode::InvalidArgument);
  EXPECT_EQ(result.failed_waypoint, 1);

  TrajectoryRequest bad_start = request_;
  bad_start.plan.start = vec({ 0.0, -0.3, 0.0, 0.0, 0.0, 0.0 });
  result = planTrajectory(*planner_, timing_, bad_start);
  EXPECT_EQ(result.code, ErrorCode::InCollision);
  EXPECT_EQ(result.failed_waypoint, -1);

  TrajectoryRequest no_time = request_;
  no_time.plan.time_limit = std::nan("");
  EXPECT_EQ(planTrajectory(*planner_, timing_, no_time).code, ErrorCode::InvalidArgument);
}

TEST_F(TrajectoryPlanningTest, SpeedScalingBoundsEveryJointAtItsFractionOfTheLimits)
{
  request_.waypoints.clear();
  request_.plan.seed = 7;
  const TrajectoryResult full = planTrajectory(*planner_, timing_, request_);
  request_.scaling = { 0.5, 0.25 };
  const TrajectoryResult slow = planTrajectory(*planner_, timing_, request_);
  ASSERT_TRUE(full.success && slow.success) << full.message << slow.message;
  double peak_velocity = 0.0, full_peak = 0.0;
  for (const auto& p : slow.trajectory.points)
    for (const double v : p.velocities)
      peak_velocity = std::max(peak_velocity, std::abs(v));
  for (const auto& p : full.trajectory.points)
    for (const double v : p.velocities)
      full_peak = std::max(full_peak, std::abs(v));
  std::cout << "full speed " << full.trajectory.duration() << " s, peak " << full_peak << " rad/s; scaled (0.5, 0.25) "
            << slow.trajectory.duration() << " s, peak " << peak_velocity << " rad/s\n";
  EXPECT_LE(peak_velocity, 0.5 * M_PI + 1e-6);
  EXPECT_GT(full_peak, 0.5 * M_PI);  // the unscaled plan needs more than the scaled limit
  // Same path (same seed); half the velocity and a quarter of the acceleration is the time-optimal
  // trajectory played at half speed: twice as long.
  EXPECT_NEAR(slow.trajectory.duration(), 2.0 * full.trajectory.duration(), 0.02 * full.trajectory.duration());
  EXPECT_LT((positions(slow.trajectory.points.back()) - *request_.plan.goal_joints).norm(), 1e-12);

  for (const SpeedScaling bad : { SpeedScaling{ 0.0, 1.0 }, SpeedScaling{ 1.0, 1.5 }, SpeedScaling{ NAN, 1.0 } })
  {
    request_.scaling = bad;
    const TrajectoryResult refused = planTrajectory(*planner_, timing_, request_);
    EXPECT_FALSE(refused.success);
    EXPECT_EQ(refused.code, ErrorCode::InvalidArgument);
    EXPECT_NE(refused.message.find("scaling_factor"), std::string::npos) << refused.message;
  }
  const SpeedScaling unset = speedScaling(0.0, 0.0);
  EXPECT_EQ(unset.velocity, 1.0);
  EXPECT_EQ(unset.acceleration, 1.0);
}

TEST_F(TrajectoryPlanningTest, APlanLongerThanTheLimitIsRefusedBeforeItIsSampled)
{
  // issue 21: max_velocity_scaling_factor 1e-6 asked for 47 M points. Refused, naming the limit, whichever
  // profile times it; the bound holds for the plan as a whole (three legs of 250 s refuse a 600 s limit).
  request_.scaling = { 1e-6, 1e-6 };
  for (const TimeProfile profile : { TimeProfile::TimeOptimal, TimeProfile::MinimumJerk })
  {
    request_.profile = profile;
    const TrajectoryResult refused = planTrajectory(*planner_, timing_, request_);
    EXPECT_FALSE(refused.success);
    EXPECT_EQ(refused.code, ErrorCode::InvalidArgument);
    EXPECT_TRUE(refused.trajectory.points.empty());
    EXPECT_EQ(refused.failed_waypoint, -1);
    EXPECT_NE(refused.message.find("a plan may last at most 600 s (60001 points)"), std::string::npos) << refused.message;
  }
  request_.profile = TimeProfile::TimeOptimal;
  request_.scaling = {};
  request_.plan.seed = 7;
  const TrajectoryResult full = planTrajectory(*planner_, timing_, request_);
  ASSERT_TRUE(full.success) << full.message;
  TimingOptions tight = timing_;
  tight.max_duration = 0.5 * full.trajectory.duration();  // every leg fits, the three together do not
  for (std::size_t leg = 0; leg < full.waypoint_times.size(); ++leg)
    ASSERT_LT(full.waypoint_times[leg] - (leg ? full.waypoint_times[leg - 1] : 0.0), tight.max_duration) << leg;
  const TrajectoryResult whole = planTrajectory(*planner_, tight, request_);
  EXPECT_FALSE(whole.success);
  EXPECT_NE(whole.message.find("trajectory: "), std::string::npos) << whole.message;
  std::cout << "refused: " << whole.message << "\n";
}

TEST_F(TrajectoryPlanningTest, MinimumJerkIsSmoothWithinTheScaledLimitsAndRestsAtEveryVertex)
{
  request_.plan.seed = 7;
  request_.scaling = { 1.0, 0.25 };
  request_.profile = TimeProfile::MinimumJerk;
  const TrajectoryResult smooth = planTrajectory(*planner_, timing_, request_);
  request_.profile = TimeProfile::TimeOptimal;
  const TrajectoryResult fast = planTrajectory(*planner_, timing_, request_);
  ASSERT_TRUE(smooth.success && fast.success) << smooth.message << fast.message;
  expectCollisionFree(smooth.trajectory);
  const auto& points = smooth.trajectory.points;
  double peak_velocity = 0.0, peak_acceleration = 0.0, largest_step = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k)
    for (std::size_t j = 0; j < 6; ++j)
    {
      peak_velocity = std::max(peak_velocity, std::abs(points[k].velocities[j]));
      peak_acceleration = std::max(peak_acceleration, std::abs(points[k].accelerations[j]));
      if (k > 0)  // no step in acceleration between 10 ms samples: bounded jerk
        largest_step = std::max(largest_step, std::abs(points[k].accelerations[j] - points[k - 1].accelerations[j]));
    }
  std::cout << "minimum jerk " << smooth.trajectory.duration() << " s (time-optimal " << fast.trajectory.duration()
            << " s), peak " << peak_velocity << " rad/s, " << peak_acceleration << " rad/s^2, largest acceleration step "
            << largest_step << " rad/s^2 in one sample\n";
  EXPECT_LE(peak_velocity, M_PI + 1e-9);
  EXPECT_LE(peak_acceleration, 0.25 * M_PI + 1e-9);
  EXPECT_GT(peak_acceleration, 0.9 * 0.25 * M_PI);  // the slowest joint of some piece uses its limit
  EXPECT_LT(largest_step, 0.05 * 0.25 * M_PI);
  EXPECT_GT(smooth.trajectory.duration(), fast.trajectory.duration());
  // at rest, without acceleration, at every vertex of the checked path; the last sample is the goal exactly
  std::size_t vertex = 0;
  for (const auto& p : points)
    if (vertex < smooth.path.size() && (positions(p) - smooth.path[vertex]).norm() < 1e-12)
    {
      for (std::size_t j = 0; j < 6; ++j)
      {
        EXPECT_NEAR(p.velocities[j], 0.0, 1e-12) << "vertex " << vertex;
        EXPECT_NEAR(p.accelerations[j], 0.0, 1e-12) << "vertex " << vertex;
      }
      ++vertex;
    }
  EXPECT_EQ(vertex, smooth.path.size());
  EXPECT_EQ(positions(points.back()), *request_.plan.goal_joints);
  for (std::size_t w = 0; w < smooth.waypoint_times.size(); ++w)
    EXPECT_GT(smooth.waypoint_times[w], w == 0 ? 0.0 : smooth.waypoint_times[w - 1]);

  try
  {
    timeProfile("trapezoid");
    ADD_FAILURE() << "an unknown profile was accepted";
  }
  catch (const KinematicsError& e)
  {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    EXPECT_NE(std::string(e.what()).find("time_profile: 'trapezoid'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(timeProfile(""), TimeProfile::TimeOptimal);
  EXPECT_EQ(timeProfile("minimum_jerk"), TimeProfile::MinimumJerk);
}
