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
