#include <gtest/gtest.h>

#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl_parser/kdl_parser.hpp>
#include <random>

#include "fixtures.h"
#include "vrrw_kinematics/kinematic_chain.h"
#include "vrrw_kinematics/kinematics_error.h"

using namespace vrrw_kinematics;

namespace
{
Eigen::Isometry3d kdlFk(const std::string& urdf, const std::string& base, const std::string& tip,
                        const Eigen::VectorXd& q)
{
  KDL::Tree tree;
  EXPECT_TRUE(kdl_parser::treeFromString(urdf, tree));
  KDL::Chain chain;
  EXPECT_TRUE(tree.getChain(base, tip, chain));
  KDL::ChainFkSolverPos_recursive solver(chain);
  KDL::JntArray joints(chain.getNrOfJoints());
  for (unsigned i = 0; i < chain.getNrOfJoints(); ++i)
    joints(i) = q[i];
  KDL::Frame frame;
  solver.JntToCart(joints, frame);
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
  {
    out.translation()[r] = frame.p[r];
    for (int c = 0; c < 3; ++c)
      out.linear()(r, c) = frame.M(r, c);
  }
  return out;
}
}  // namespace

TEST(KinematicChain, Ur5eZeroAndHomeMatchHandComputedPoses)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0");
  ASSERT_EQ(chain.size(), 6u);
  // At zero the UR arm lies along -x of the DH base, which ur_description turns by pi about z:
  // x = -(a2 + a3), y = d4 + d6, z = d1 - d5.
  const Eigen::Isometry3d zero = chain.fk(Eigen::VectorXd::Zero(6));
  EXPECT_NEAR(zero.translation().x(), 0.425 + 0.3922, 1e-9);
  EXPECT_NEAR(zero.translation().y(), 0.1333 + 0.0996, 1e-9);
  EXPECT_NEAR(zero.translation().z(), 0.1625 - 0.0997, 1e-9);
  // Home [0, -pi/2, 0, -pi/2, 0, 0]: upper arm and forearm vertical, wrist 2 above the forearm.
  Eigen::VectorXd home(6);
  home << 0, -M_PI / 2, 0, -M_PI / 2, 0, 0;
  const Eigen::Isometry3d up = chain.fk(home);
  EXPECT_NEAR(up.translation().x(), 0.0, 1e-9);
  EXPECT_NEAR(up.translation().y(), 0.1333 + 0.0996, 1e-9);
  EXPECT_NEAR(up.translation().z(), 0.1625 + 0.425 + 0.3922 + 0.0997, 1e-9);
}

TEST(KinematicChain, PandaZeroMatchesPublishedFlangePose)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8");
  ASSERT_EQ(chain.size(), 7u);
  const Eigen::Isometry3d zero = chain.fk(Eigen::VectorXd::Zero(7));
  EXPECT_NEAR(zero.translation().x(), 0.088, 1e-12);
  EXPECT_NEAR(zero.translation().y(), 0.0, 1e-12);
  EXPECT_NEAR(zero.translation().z(), 0.333 + 0.316 + 0.384 - 0.107, 1e-12);
  EXPECT_NEAR(zero.linear()(2, 2), -1.0, 1e-12);
}

TEST(KinematicChain, PrismaticAndContinuousJoints)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("gantry.urdf"), "base", "tip");
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_TRUE(chain.joints()[0].prismatic);
  EXPECT_TRUE(chain.joints()[2].continuous);
  Eigen::VectorXd q(3);
  q << 0.3, M_PI / 2, 0.0;
  const Eigen::Isometry3d tip = chain.fk(q);
  EXPECT_NEAR(tip.translation().x(), 0.3, 1e-12);
  EXPECT_NEAR(tip.translation().y(), 0.8, 1e-12);
  EXPECT_NEAR(tip.translation().z(), 1.0, 1e-12);
  EXPECT_NEAR(chain.fk(q, "arm2").translation().y(), 0.5, 1e-12);
}

TEST(KinematicChain, AgreesWithKdlOnEveryFixture)
{
  struct Case { const char* file; const char* base; const char* tip; };
  std::mt19937_64 rng(3);
  for (const Case c : { Case{ "ur5e.urdf", "base_link", "tool0" }, Case{ "panda.urdf", "panda_link0", "panda_link8" },
                        Case{ "iiwa14.urdf", "iiwa_link0", "iiwa_link8" }, Case{ "gantry.urdf", "base", "tip" } })
  {
    const std::string urdf = fixture(c.file);
    const KinematicChain chain = KinematicChain::fromUrdf(urdf, c.base, c.tip);
    double worst = 0.0;
    for (int s = 0; s < 200; ++s)
    {
      const Eigen::VectorXd q = chain.randomState(rng);
      worst = std::max(worst, (chain.fk(q).matrix() - kdlFk(urdf, c.base, c.tip, q).matrix()).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-9) << c.file;
  }
}

TEST(KinematicChain, JacobianMatchesFiniteDifferences)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("gantry.urdf"), "base", "tip");
  const KinematicChain panda = KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8");
  std::mt19937_64 rng(5);
  for (const KinematicChain* c : { &chain, &panda })
  {
    const Eigen::VectorXd q = c->randomState(rng);
    Eigen::Isometry3d tip;
    Eigen::Matrix<double, 6, Eigen::Dynamic> jac;
    c->jacobian(q, tip, jac);
    EXPECT_LT((tip.matrix() - c->fk(q).matrix()).norm(), 1e-15);
    const double h = 1e-7;
    for (std::size_t i = 0; i < c->size(); ++i)
    {
      Eigen::VectorXd dq = q;
      dq[i] += h;
      const Eigen::Isometry3d moved = c->fk(dq);
      const Eigen::Vector3d linear = (moved.translation() - tip.translation()) / h;
      const Eigen::Vector3d angular = rotationError(moved.linear(), tip.linear()) / h;
      EXPECT_LT((linear - jac.col(i).head<3>()).norm(), 1e-5);
      EXPECT_LT((angular - jac.col(i).tail<3>()).norm(), 1e-5);
    }
  }
}

TEST(KinematicChain, BadChainsAreNamed)
{
  const std::string urdf = fixture("gantry.urdf");
  try
  {
    KinematicChain::fromUrdf(urdf, "tip", "side");
    FAIL();
  }
  catch (const KinematicsError& e)
  {
    EXPECT_EQ(e.code(), ErrorCode::NotSerialChain);
    EXPECT_NE(std::string(e.what()).find("side"), std::string::npos);
  }
  try
  {
    KinematicChain::fromUrdf(urdf, "base", "nowhere");
    FAIL();
  }
  catch (const KinematicsError& e)
  {
    EXPECT_EQ(e.code(), ErrorCode::UnknownLink);
  }
  const KinematicChain chain = KinematicChain::fromUrdf(urdf, "base", "tip");
  Eigen::VectorXd q(3);
  q << 1.5, 0, 0;
  EXPECT_EQ(chain.jointOutsideLimits(q), "slide");
  q[0] = std::nan("");
  EXPECT_FALSE(chain.withinLimits(q));
  EXPECT_THROW(chain.fk(q.setZero(), "side"), KinematicsError);
}
