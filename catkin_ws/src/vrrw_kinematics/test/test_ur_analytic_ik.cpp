#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "vrrw_kinematics/ur_analytic_ik.h"

using namespace vrrw_kinematics;

namespace
{
double poseDistance(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
  return std::max((a.translation() - b.translation()).norm(), rotationError(a.linear(), b.linear()).norm());
}

double wrappedDistance(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    worst = std::max(worst, std::abs(std::remainder(a[i] - b[i], 2 * M_PI)));
  return worst;
}
}  // namespace

TEST(URAnalyticIK, DetectsUr5eParametersFromTheUrdf)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0");
  const auto ik = URAnalyticIK::detect(chain);
  ASSERT_TRUE(ik.has_value());
  const URParameters& p = ik->parameters();
  EXPECT_NEAR(p.d1, 0.1625, 1e-9);
  EXPECT_NEAR(std::abs(p.a2), 0.425, 1e-9);
  EXPECT_NEAR(std::abs(p.a3), 0.3922, 1e-9);
  EXPECT_NEAR(std::abs(p.d4), 0.1333, 1e-9);
  EXPECT_NEAR(std::abs(p.d5), 0.0997, 1e-9);
  EXPECT_NEAR(std::abs(p.d6), 0.0996, 1e-9);
}

TEST(URAnalyticIK, RejectsOtherArms)
{
  EXPECT_FALSE(URAnalyticIK::detect(KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8")));
  EXPECT_FALSE(URAnalyticIK::detect(KinematicChain::fromUrdf(fixture("iiwa14.urdf"), "iiwa_link0", "iiwa_link8")));
  EXPECT_FALSE(URAnalyticIK::detect(KinematicChain::fromUrdf(fixture("gantry.urdf"), "base", "tip")));
}

TEST(URAnalyticIK, EightSolutionsRoundTrip)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0");
  const auto ik = URAnalyticIK::detect(chain);
  ASSERT_TRUE(ik.has_value());
  std::mt19937_64 rng(11);
  int eight = 0;
  double worst_pose = 0.0;
  const int samples = 2000;
  for (int s = 0; s < samples; ++s)
  {
    const Eigen::VectorXd q = chain.randomState(rng);
    const Eigen::Isometry3d target = chain.fk(q);
    const std::vector<Eigen::VectorXd> all = ik->solveAll(target, Eigen::VectorXd::Zero(6));
    eight += all.size() == 8 ? 1 : 0;
    EXPECT_GE(all.size(), 2u);
    EXPECT_EQ(all.size() % 2, 0u);
    bool found_original = false;
    for (const Eigen::VectorXd& solution : all)
    {
      worst_pose = std::max(worst_pose, poseDistance(chain.fk(solution), target));
      found_original = found_original || wrappedDistance(solution, q) < 1e-6;
      EXPECT_TRUE(chain.withinLimits(solution));
    }
    EXPECT_TRUE(found_original) << "sample " << s;
    Eigen::VectorXd nearest;
    ASSERT_TRUE(ik->solveNearest(target, q, nearest));
    EXPECT_LT((nearest - q).norm(), 1e-6);
  }
  EXPECT_LT(worst_pose, 1e-9);
  // About 77% of uniform random UR5e poses have all 8 solutions; elsewhere the other shoulder or
  // wrist branch cannot reach the wrist centre (measured 1543 of 2000 with an independent script).
  EXPECT_GT(eight, samples * 70 / 100);
}

TEST(URAnalyticIK, UnreachablePoseHasNoSolution)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0");
  const auto ik = URAnalyticIK::detect(chain);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 2.0, 0.0, 0.5;
  EXPECT_TRUE(ik->solveAll(far, Eigen::VectorXd::Zero(6)).empty());
  Eigen::VectorXd q;
  EXPECT_FALSE(ik->solveNearest(far, Eigen::VectorXd::Zero(6), q));
}
