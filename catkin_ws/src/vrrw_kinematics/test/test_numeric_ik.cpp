#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "fixtures.h"
#include "vrrw_kinematics/numeric_ik.h"

using namespace vrrw_kinematics;

namespace
{
struct Tally
{
  int success = 0;
  double worst_position = 0.0;
  double worst_orientation = 0.0;
};

Tally roundTrip(const KinematicChain& chain, const IkOptions& options, int samples)
{
  const NumericIK ik(chain);
  std::mt19937_64 rng(21);
  Tally tally;
  for (int s = 0; s < samples; ++s)
  {
    const Eigen::Isometry3d target = chain.fk(chain.randomState(rng));
    const IkResult result = ik.solve(target, chain.midLimits(), options);
    if (!result.success)
      continue;
    EXPECT_TRUE(chain.withinLimits(result.q));
    const Eigen::Isometry3d reached = chain.fk(result.q);
    tally.worst_position = std::max(tally.worst_position, (reached.translation() - target.translation()).norm());
    tally.worst_orientation =
        std::max(tally.worst_orientation, rotationError(target.linear(), reached.linear()).norm());
    ++tally.success;
  }
  return tally;
}
}  // namespace

TEST(NumericIK, PandaAndIiwaRoundTrips)
{
  IkOptions options;
  // a budget, not a verdict: the search returns at its first solution (a few ms); only a target it
  // cannot solve spends it, so a loaded machine (fewer restarts per second) finds the same solutions
  options.timeout = 0.5;
  for (const auto& c : { std::make_pair("panda.urdf", "panda"), std::make_pair("iiwa14.urdf", "iiwa") })
  {
    const std::string prefix = c.second;
    const KinematicChain chain = KinematicChain::fromUrdf(fixture(c.first), prefix + "_link0", prefix + "_link8");
    const Tally tally = roundTrip(chain, options, 300);
    EXPECT_GE(tally.success, 299) << c.first;
    EXPECT_LE(tally.worst_position, 1e-5);
    EXPECT_LE(tally.worst_orientation, 1e-5);
  }
}

TEST(NumericIK, SolvesUr5eNumericallyToo)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("ur5e.urdf"), "base_link", "tool0");
  IkOptions options;
  options.timeout = 0.5;
  EXPECT_GE(roundTrip(chain, options, 200).success, 199);
}

TEST(NumericIK, FiveDofChainReachesItsOwnPoses)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link5");
  ASSERT_EQ(chain.size(), 5u);
  IkOptions options;
  options.timeout = 0.5;
  const Tally tally = roundTrip(chain, options, 200);
  EXPECT_GE(tally.success, 198);
  EXPECT_LE(tally.worst_position, 1e-5);
  EXPECT_LE(tally.worst_orientation, 1e-5);
}

TEST(NumericIK, PositionOnlyOnPrismaticChain)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("gantry.urdf"), "base", "tip");
  IkOptions options;
  options.mode = IkOptions::Mode::PositionOnly;
  const Tally tally = roundTrip(chain, options, 200);
  EXPECT_EQ(tally.success, 200);
  EXPECT_LE(tally.worst_position, 1e-5);
}

TEST(NumericIK, OrientationTolerantStaysWithinTolerance)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8");
  const NumericIK ik(chain);
  std::mt19937_64 rng(4);
  IkOptions options;
  options.mode = IkOptions::Mode::OrientationTolerant;
  options.orientation_tolerance = 0.2;
  options.timeout = 0.5;
  int success = 0;
  for (int s = 0; s < 100; ++s)
  {
    Eigen::Isometry3d target = chain.fk(chain.randomState(rng));
    target.linear() = target.linear() * Eigen::AngleAxisd(0.15, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const IkResult result = ik.solve(target, chain.midLimits(), options);
    if (!result.success)
      continue;
    ++success;
    const Eigen::Isometry3d reached = chain.fk(result.q);
    EXPECT_LE((reached.translation() - target.translation()).norm(), 1e-5);
    EXPECT_LE(rotationError(target.linear(), reached.linear()).norm(), 0.2 + 1e-5);
  }
  EXPECT_GE(success, 99);
}

TEST(NumericIK, NearestModeSearchesUntilTheTimeout)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8");
  const NumericIK ik(chain);
  std::mt19937_64 rng(12);
  // The first-solution search returns as soon as it has one: a generous budget costs nothing when the
  // machine is idle and keeps a loaded machine (fewer restarts per second) from failing it.
  IkOptions first;
  first.timeout = 1.0;
  IkOptions nearest = first;
  nearest.nearest = true;
  for (int s = 0; s < 10; ++s)
  {
    const Eigen::Isometry3d target = chain.fk(chain.randomState(rng));
    const Eigen::VectorXd seed = chain.randomState(rng);
    const auto start = std::chrono::steady_clock::now();
    const IkResult quick = ik.solve(target, seed, first);
    // The nearest search repeats the same seeded restarts, so with twice the time the first search took
    // (and 200 ms: a scheduler pause of a loaded machine is tens of ms) it reaches the first solution and keeps
    // going, however busy the machine.
    nearest.timeout = 0.2 + 2.0 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const IkResult thorough = ik.solve(target, seed, nearest);
    ASSERT_TRUE(quick.success) << s << " " << quick.message;
    ASSERT_TRUE(thorough.success) << s << " " << thorough.message;
    EXPECT_GT(thorough.attempts, quick.attempts);
    EXPECT_LE((thorough.q - seed).norm(), (quick.q - seed).norm() + 1e-12);
    EXPECT_LE(thorough.position_error, 1e-5);
  }
}

TEST(NumericIK, ContinuousJointStaysOnTheSeedsTurn)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("gantry.urdf"), "base", "tip");
  ASSERT_TRUE(chain.joints()[2].continuous);
  Eigen::VectorXd q(3);
  q << 0.2, 0.5, 2.0 * M_PI + 0.4;  // two-joint planar arm, the last joint one turn on
  const NumericIK ik(chain);
  IkOptions options;
  options.mode = IkOptions::Mode::PositionOnly;
  Eigen::VectorXd seed = q;
  seed[2] += 0.05;
  const IkResult result = ik.solve(chain.fk(q), seed, options);
  ASSERT_TRUE(result.success);
  EXPECT_TRUE(chain.withinLimits(result.q));
  EXPECT_NEAR(result.q[2], q[2], 0.2);
}

TEST(NumericIK, UnreachableTargetTimesOut)
{
  const KinematicChain chain = KinematicChain::fromUrdf(fixture("panda.urdf"), "panda_link0", "panda_link8");
  const NumericIK ik(chain);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() << 3.0, 0.0, 0.0;
  IkOptions options;
  options.timeout = 0.05;  // several restarts even on a loaded machine
  const IkResult result = ik.solve(far, chain.midLimits(), options);
  EXPECT_FALSE(result.success);
  EXPECT_EQ(result.code, ErrorCode::NoSolution);
  EXPECT_GT(result.attempts, 1);
  EXPECT_NE(result.message.find("panda_link8"), std::string::npos);
}
