// The library on the shipped robot descriptions: every arm of paper_multibot (UR3e, UR5e, UR10e with
// Robotiq grippers, Fetch) and pick_place_drill, expanded by vrrw_scene::loadScene.
#include <gtest/gtest.h>

#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl_parser/kdl_parser.hpp>
#include <algorithm>
#include <random>
#include <vrrw_scene/scene_loader.h>

#include "vrrw_kinematics/ik_solver.h"
#include "vrrw_kinematics/motion_planner.h"
#include "vrrw_kinematics/scene_state.h"
#include "vrrw_kinematics/time_parameterization.h"

using namespace vrrw_kinematics;

namespace
{
const vrrw_scene::Scene& multibot()
{
  static const vrrw_scene::Scene scene = vrrw_scene::loadScene("paper_multibot");
  return scene;
}
}  // namespace

TEST(ShippedScenes, FkAgreesWithKdlOnEveryArm)
{
  const RobotModel model = RobotModel::fromUrdf(multibot().urdf);
  KDL::Tree tree;
  ASSERT_TRUE(kdl_parser::treeFromString(multibot().urdf, tree));
  for (const vrrw_scene::Robot& robot : multibot().robots)
  {
    const KinematicChain chain(model, robot.arm_base_link, robot.tcp_link);
    KDL::Chain kdl_chain;
    ASSERT_TRUE(tree.getChain(robot.arm_base_link, robot.tcp_link, kdl_chain));
    ASSERT_EQ(kdl_chain.getNrOfJoints(), chain.size());
    KDL::ChainFkSolverPos_recursive solver(kdl_chain);
    std::mt19937_64 rng(2);
    double worst = 0.0;
    for (int s = 0; s < 100; ++s)
    {
      const Eigen::VectorXd q = chain.randomState(rng);
      KDL::JntArray joints(kdl_chain.getNrOfJoints());
      for (unsigned i = 0; i < kdl_chain.getNrOfJoints(); ++i)
        joints(i) = q[i];
      KDL::Frame frame;
      solver.JntToCart(joints, frame);
      const Eigen::Isometry3d pose = chain.fk(q);
      for (int r = 0; r < 3; ++r)
      {
        worst = std::max(worst, std::abs(pose.translation()[r] - frame.p[r]));
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(pose.linear()(r, c) - frame.M(r, c)));
      }
    }
    EXPECT_LT(worst, 1e-9) << robot.name;
  }
}

TEST(ShippedScenes, IkRoundTripsOnEveryArm)
{
  const RobotModel model = RobotModel::fromUrdf(multibot().urdf);
  for (const vrrw_scene::Robot& robot : multibot().robots)
  {
    const IkSolver solver(KinematicChain(model, robot.arm_base_link, robot.tcp_link));
    EXPECT_EQ(solver.chain().jointNames(), robot.arm_joints) << robot.name;
    EXPECT_EQ(solver.hasAnalytic(), robot.model != "fetch") << robot.name;
    std::mt19937_64 rng(17);
    IkOptions options;
    options.timeout = 0.5;  // a budget, not the verdict: the search returns at its first solution
    int success = 0;
    const int samples = 300;
    for (int s = 0; s < samples; ++s)
    {
      const Eigen::VectorXd q = solver.chain().randomState(rng);
      const Eigen::Isometry3d target = solver.chain().fk(q);
      const IkResult result = solver.solve(target, solver.chain().midLimits(), options);
      if (!result.success)
        continue;
      ++success;
      const Eigen::Isometry3d reached = solver.chain().fk(result.q);
      EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-5);
      EXPECT_LT(rotationError(target.linear(), reached.linear()).norm(), 1e-5);
      EXPECT_TRUE(solver.chain().withinLimits(result.q));
    }
    EXPECT_GE(success, samples - 1) << robot.name;
  }
}

TEST(ShippedScenes, FastCheckerAgreesWithFullCheckForEveryArm)
{
  CollisionWorld world = CollisionWorld::fromScene(multibot());
  world.loadOrComputeAllowedCollisions(multibot().cache_dir);
  EXPECT_GT(world.acm().count("adjacent"), 40u);
  EXPECT_GT(world.acm().count("never"), 0u);  // e.g. Fetch's head and its wheels
  EXPECT_EQ(world.acm().reason("fetch_head_tilt_link", "fetch_l_wheel_link"), "never");
  const Eigen::VectorXd initial = initialState(world.model(), multibot());
  EXPECT_FALSE(world.check(initial).collision) << world.check(initial).body_a << " - " << world.check(initial).body_b;
  for (const vrrw_scene::Robot& robot : multibot().robots)
  {
    StateChecker checker(world, robot.arm_joints, initial);
    std::mt19937_64 rng(4);
    int collisions = 0;
    for (int s = 0; s < 300; ++s)
    {
      Eigen::VectorXd state = initial;
      Eigen::VectorXd q(static_cast<Eigen::Index>(robot.arm_joints.size()));
      for (std::size_t i = 0; i < robot.arm_joints.size(); ++i)
      {
        const JointModel& joint = world.model().joints()[world.model().jointIndex(robot.arm_joints[i])];
        q[static_cast<Eigen::Index>(i)] = std::uniform_real_distribution<double>(joint.lower, joint.upper)(rng);
        state[joint.variable] = q[static_cast<Eigen::Index>(i)];
      }
      const bool full = world.check(state).collision;
      ASSERT_EQ(checker.valid(q), !full) << robot.name << " sample " << s;
      collisions += full ? 1 : 0;
    }
    EXPECT_GT(collisions, 0) << robot.name;
  }
}

TEST(ShippedScenes, ArmAccelerationLimitsFollowTheArmOrder)
{
  EXPECT_EQ(armAccelerationLimits(*multibot().robot("ur5e")), std::vector<double>(6, 3.14159265));
  EXPECT_EQ(armAccelerationLimits(*multibot().robot("fetch")),
            (std::vector<double>{ 1.5, 1.0, 1.5, 1.5, 1.5, 2.5, 2.5 }));  // urdf/config/fetch.yaml
  vrrw_scene::Robot robot = *multibot().robot("ur3e");
  robot.acceleration_limits.erase("ur3e_elbow_joint");
  try
  {
    armAccelerationLimits(robot);
    FAIL();
  }
  catch (const KinematicsError& e)
  {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    EXPECT_NE(std::string(e.what()).find("ur3e_elbow_joint"), std::string::npos) << e.what();
  }
}

TEST(ShippedScenes, PlannedTrajectoriesAreCollisionFreeAndWithinLimits)
{
  CollisionWorld world = CollisionWorld::fromScene(multibot());
  world.loadOrComputeAllowedCollisions(multibot().cache_dir);
  const Eigen::VectorXd initial = initialState(world.model(), multibot());
  for (const vrrw_scene::Robot& robot : multibot().robots)
  {
    MotionPlanner planner(world, robot.arm_joints, robot.tcp_link, initial);
    TimingOptions timing;
    for (const std::string& joint : robot.arm_joints)
      timing.max_velocity.push_back(world.model().joints()[world.model().jointIndex(joint)].max_velocity);
    timing.max_acceleration = armAccelerationLimits(robot);
    timing.max_deviation = 0.0;
    const TimeParameterization parameterization(timing);
    Eigen::VectorXd home(static_cast<Eigen::Index>(robot.arm_joints.size()));
    for (std::size_t i = 0; i < robot.arm_joints.size(); ++i)
      home[static_cast<Eigen::Index>(i)] = initial[world.model().variableIndex(robot.arm_joints[i])];
    std::mt19937_64 rng(6);
    for (int query = 0; query < 3; ++query)
    {
      Eigen::VectorXd goal = home;
      do
      {
        for (Eigen::Index i = 0; i < goal.size(); ++i)
          goal[i] = std::max(planner.lowerLimits()[i],
                             std::min(planner.upperLimits()[i],
                                      home[i] + std::uniform_real_distribution<double>(-1.5, 1.5)(rng)));
      } while (!planner.stateValid(goal));
      PlanRequest request;
      request.start = home;
      request.goal_joints = goal;
      request.seed = static_cast<std::uint64_t>(query + 1);
      const PlanResult result = planner.plan(request);
      ASSERT_TRUE(result.success) << robot.name << ": " << result.message;
      EXPECT_TRUE(planner.pathValid(result.path));
      // Every trajectory sample lies on the checked path (no blends); recheck the sampled motion.
      const auto trajectory = parameterization.compute(result.path, robot.arm_joints);
      Eigen::VectorXd previous = home;
      for (const auto& point : trajectory.points)
      {
        const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(point.positions.data(), goal.size());
        EXPECT_TRUE(planner.segmentValid(previous, q)) << robot.name << " t=" << point.time;
        for (std::size_t i = 0; i < robot.arm_joints.size(); ++i)
        {
          EXPECT_LE(std::abs(point.velocities[i]), timing.max_velocity[i] * (1 + 1e-9));
          EXPECT_LE(std::abs(point.accelerations[i]), timing.max_acceleration[i] * (1 + 1e-9));
        }
        previous = q;
      }
      EXPECT_LT((previous - goal).norm(), 1e-9);
    }
  }
}

TEST(ShippedScenes, ContinuousJointsPlanFromAnyTurn)
{
  CollisionWorld world = CollisionWorld::fromScene(multibot());
  world.loadOrComputeAllowedCollisions(multibot().cache_dir);
  const Eigen::VectorXd initial = initialState(world.model(), multibot());
  const vrrw_scene::Robot& fetch = *multibot().robot("fetch");
  MotionPlanner planner(world, fetch.arm_joints, fetch.tcp_link, initial);
  Eigen::VectorXd start(static_cast<Eigen::Index>(fetch.arm_joints.size()));
  for (std::size_t i = 0; i < fetch.arm_joints.size(); ++i)
    start[static_cast<Eigen::Index>(i)] = initial[world.model().variableIndex(fetch.arm_joints[i])];
  const auto roll = std::find(fetch.arm_joints.begin(), fetch.arm_joints.end(), "fetch_wrist_roll_joint");
  ASSERT_NE(roll, fetch.arm_joints.end());
  const Eigen::Index r = roll - fetch.arm_joints.begin();
  start[r] += 4.0 * M_PI + 0.3;  // two turns on, as a joint state may report
  Eigen::VectorXd goal = start;
  goal[r] = -0.2;  // the same as 4 pi - 0.2, 0.5 rad away
  PlanRequest request;
  request.start = start;
  request.goal_joints = goal;
  const PlanResult result = planner.plan(request);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_NEAR(result.path.back()[r], 4.0 * M_PI - 0.2, 1e-9);
  EXPECT_NEAR(result.path_length, 0.5, 1e-9);
}
