#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "vrrw_kinematics/ik_solver.h"

using namespace vrrw_kinematics;

TEST(IkSolver, Ur5eUsesClosedFormAndReturnsNearestSolution)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  ASSERT_TRUE(solver.hasAnalytic());
  std::mt19937_64 rng(8);
  for (int s = 0; s < 500; ++s)
  {
    const Eigen::VectorXd q = solver.chain().randomState(rng);
    const Eigen::VectorXd seed = q + 0.05 * Eigen::VectorXd::Ones(6);
    const IkResult result = solver.solve(solver.chain().fk(q), seed);
    ASSERT_TRUE(result.success) << result.message;
    EXPECT_LE((result.q - seed).norm(), (q - seed).norm() + 1e-9);
    EXPECT_LT(result.position_error, 1e-9);
  }
}

TEST(IkSolver, Ur5eAtWristSingularity)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  Eigen::VectorXd q(6);
  q << 0.4, -1.2, 1.1, -0.7, 0.0, 0.3;  // wrist 2 at zero: wrist 1 and wrist 3 axes line up
  const IkResult result = solver.solve(solver.chain().fk(q), q);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LT(result.position_error, 1e-5);
  EXPECT_LT(result.orientation_error, 1e-5);
}

TEST(IkSolver, PandaFallsBackToNumeric)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8"));
  EXPECT_FALSE(solver.hasAnalytic());
  EXPECT_TRUE(solver.solveAll(Eigen::Isometry3d::Identity(), Eigen::VectorXd::Zero(7)).empty());
  Eigen::VectorXd q(7);
  q << 0.3, -0.4, 0.2, -2.0, 0.1, 1.8, 0.5;
  const IkResult result = solver.solve(solver.chain().fk(q), solver.chain().midLimits());
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LE(result.position_error, 1e-5);
}

TEST(IkSolver, BadInputGivesCodesAndMessages)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  const Eigen::VectorXd seed = Eigen::VectorXd::Zero(6);
  Eigen::Isometry3d nan_pose = Eigen::Isometry3d::Identity();
  nan_pose.translation().x() = std::nan("");
  EXPECT_EQ(solver.solve(nan_pose, seed).code, ErrorCode::InvalidPose);
  Eigen::Isometry3d sheared = Eigen::Isometry3d::Identity();
  sheared.linear()(0, 1) = 0.3;
  EXPECT_EQ(solver.solve(sheared, seed).code, ErrorCode::InvalidPose);
  EXPECT_EQ(solver.solve(Eigen::Isometry3d::Identity(), Eigen::VectorXd::Zero(5)).code, ErrorCode::InvalidArgument);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 5.0, 0, 0;
  const IkResult unreachable = solver.solve(far, seed);
  EXPECT_EQ(unreachable.code, ErrorCode::NoSolution);
  EXPECT_NE(unreachable.message.find("tool0"), std::string::npos);

  EXPECT_THROW(poseFromQuaternion(Eigen::Vector3d::Zero(), Eigen::Vector4d(0, 0, 0, 2)), KinematicsError);
  EXPECT_THROW(poseFromQuaternion(Eigen::Vector3d::Zero(), Eigen::Vector4d(0, 0, std::nan(""), 1)), KinematicsError);
  const Eigen::Isometry3d ok = poseFromQuaternion(Eigen::Vector3d(1, 2, 3), Eigen::Vector4d(0, 0, std::sqrt(0.5), std::sqrt(0.5)));
  EXPECT_NEAR(ok.linear()(1, 0), 1.0, 1e-12);
}

namespace
{
const CollisionTest kNothingCollides = [](const Eigen::VectorXd&) { return Contact{}; };

double largestJump(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  return (a - b).cwiseAbs().maxCoeff();
}
}  // namespace

TEST(IkSolverCollisionFree, ReturnsTheNearestSolutionTheTestAccepts)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  // A stand-in obstacle: every configuration with the elbow bent upwards (elbow_joint > 0) collides.
  int tests = 0;
  const CollisionTest elbow_down = [&](const Eigen::VectorXd& q) {
    ++tests;
    return q[2] > 0.0 ? Contact{ true, "forearm_link", "obstacle" } : Contact{};
  };
  std::mt19937_64 rng(3);
  int checked = 0;
  for (int s = 0; s < 300; ++s)
  {
    const Eigen::VectorXd q = solver.chain().randomState(rng);
    const Eigen::Isometry3d target = solver.chain().fk(q);
    const Eigen::VectorXd seed = solver.chain().randomState(rng);
    std::vector<Eigen::VectorXd> free;
    for (const Eigen::VectorXd& candidate : solver.solveAll(target, seed))
      if (candidate[2] <= 0.0)
        free.push_back(candidate);
    const IkResult result = solver.solveCollisionFree(target, seed, {}, elbow_down);
    if (free.empty())
    {
      EXPECT_FALSE(result.success);
      continue;
    }
    ASSERT_TRUE(result.success) << result.message;
    ++checked;
    EXPECT_LE(result.q[2], 0.0);
    EXPECT_LT(result.position_error, 1e-9);
    EXPECT_LT(result.orientation_error, 1e-9);
    const Eigen::Isometry3d reached = solver.chain().fk(result.q);
    EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-9);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::VectorXd& candidate : free)
      nearest = std::min(nearest, (candidate - seed).norm());
    EXPECT_NEAR((result.q - seed).norm(), nearest, 1e-9);
    EXPECT_NEAR(result.jump, largestJump(result.q, seed), 1e-12);
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(tests, checked);
}

TEST(IkSolverCollisionFree, RefusesABranchFlipBeyondTheJumpBound)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  const Eigen::VectorXd q = vec({ 0.4, -1.2, 1.1, -1.5, -1.4, 0.3 });
  const Eigen::Isometry3d target = solver.chain().fk(q);
  IkOptions options;
  options.max_jump = 0.3;
  const IkResult near = solver.solveCollisionFree(target, q + 0.05 * Eigen::VectorXd::Ones(6), options, kNothingCollides);
  ASSERT_TRUE(near.success) << near.message;
  EXPECT_LT(largestJump(near.q, q), 1e-9);
  EXPECT_NEAR(near.jump, 0.05, 1e-9);

  // From the other elbow branch every solution is more than 0.3 rad away: refused, not flipped.
  Eigen::VectorXd other_branch = q;
  other_branch[2] = -1.1;
  const IkResult flip = solver.solveCollisionFree(target, other_branch, options, kNothingCollides);
  EXPECT_FALSE(flip.success);
  EXPECT_EQ(flip.code, ErrorCode::JointJump);
  EXPECT_GT(flip.jump, 0.3);
  EXPECT_NE(flip.message.find("branch flip"), std::string::npos) << flip.message;
  options.max_jump = std::numeric_limits<double>::infinity();
  const IkResult unbounded = solver.solveCollisionFree(target, other_branch, options, kNothingCollides);
  ASSERT_TRUE(unbounded.success);
  EXPECT_NEAR(unbounded.jump, flip.jump, 1e-9);
}

TEST(IkSolverCollisionFree, NamesThePairWhenEverySolutionCollides)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  const CollisionTest everything = [](const Eigen::VectorXd&) { return Contact{ true, "wrist_3_link", "pillar" }; };
  const Eigen::VectorXd q = vec({ 0.4, -1.2, 1.1, -1.5, -1.4, 0.3 });
  const IkResult result = solver.solveCollisionFree(solver.chain().fk(q), q, {}, everything);
  EXPECT_EQ(result.code, ErrorCode::InCollision);
  EXPECT_EQ(result.contact.body_a, "wrist_3_link");
  EXPECT_EQ(result.contact.body_b, "pillar");
  EXPECT_NE(result.message.find("wrist_3_link - pillar"), std::string::npos) << result.message;
}

TEST(IkSolverCollisionFree, UnreachableReportsTheResidual)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0"));
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 3.0, 0.0, 0.0;
  const IkResult result = solver.solveCollisionFree(far, vec({ 0, -1.57, 0, -1.57, 0, 0 }), {}, kNothingCollides);
  EXPECT_EQ(result.code, ErrorCode::NoSolution);
  // The UR5e reaches about 1.0 m from its shoulder: the closest pose is about 2 m short of the target.
  EXPECT_GT(result.position_error, 1.7);
  EXPECT_LT(result.position_error, 2.3);
  EXPECT_NE(result.message.find("residual"), std::string::npos) << result.message;
}

TEST(IkSolverCollisionFree, NumericChainStaysNearTheSeed)
{
  const IkSolver solver(KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8"));
  const Eigen::VectorXd q = vec({ 0.3, -0.4, 0.2, -2.0, 0.1, 1.8, 0.5 });
  IkOptions options;
  options.max_jump = 0.2;
  const IkResult result =
      solver.solveCollisionFree(solver.chain().fk(q), q + 0.02 * Eigen::VectorXd::Ones(7), options, kNothingCollides);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_LE(result.position_error, 1e-5);
  EXPECT_LE(result.orientation_error, 1e-5);
  EXPECT_LE(result.jump, 0.2);

  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 2.0, 0.0, 0.3;
  options.timeout = 0.002;
  const IkResult unreachable = solver.solveCollisionFree(far, q, options, kNothingCollides);
  EXPECT_EQ(unreachable.code, ErrorCode::NoSolution);
  EXPECT_GT(unreachable.position_error, 0.8);
  EXPECT_GE(unreachable.attempts, 1);
}
