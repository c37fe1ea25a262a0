#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "scene_fixtures.h"
#include "vrrw_kinematics/kinematic_chain.h"
#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/state_checker.h"

using namespace vrrw_kinematics;

namespace
{
const std::vector<std::string> kJoints = { "shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                           "wrist_1_joint", "wrist_2_joint", "wrist_3_joint" };
}

TEST(StateChecker, AgreesWithFullWorldCheck)
{
  CollisionWorld world(fixture("ur5e.urdf"), { slab("floor", Eigen::Vector3d(0, 0, -0.05), Eigen::Vector3d(2, 2, 0.1)),
                                               ball("ball", Eigen::Vector3d(0.4, 0.3, 0.4), 0.15) });
  world.computeAllowedCollisions(1000, 1);
  StateChecker checker(world, kJoints, Eigen::VectorXd::Zero(6));
  const KinematicChain chain(world.model(), "base_link", "tool0");
  std::mt19937_64 rng(2);
  int collisions = 0;
  for (int s = 0; s < 3000; ++s)
  {
    const Eigen::VectorXd q = chain.randomState(rng);
    const Contact full = world.check(q);
    const Contact fast = checker.check(q);
    ASSERT_EQ(full.collision, fast.collision) << "sample " << s;
    EXPECT_EQ(checker.valid(q), !full.collision);
    collisions += full.collision ? 1 : 0;
  }
  EXPECT_GT(collisions, 300);
  EXPECT_LT(collisions, 2700);
}

TEST(StateChecker, ReachBoundsEveryDisplacement)
{
  CollisionWorld world(fixture("ur5e.urdf"));
  StateChecker checker(world, kJoints, Eigen::VectorXd::Zero(6));
  ASSERT_EQ(checker.reach().size(), 6u);
  EXPECT_GT(checker.reach()[0], 0.9);
  EXPECT_LT(checker.reach()[0], 1.5);
  EXPECT_LT(checker.reach()[5], 0.1);
  const KinematicChain chain(world.model(), "base_link", "tool0");
  std::mt19937_64 rng(9);
  std::vector<Eigen::Isometry3d> before, after;
  for (int s = 0; s < 500; ++s)
  {
    const Eigen::VectorXd q = chain.randomState(rng);
    const Eigen::VectorXd dq = 0.02 * Eigen::VectorXd::Random(6);
    double bound = 0.0;
    for (int i = 0; i < 6; ++i)
      bound += checker.reach()[i] * std::abs(dq[i]);
    world.bodyTransforms(q, before);
    world.bodyTransforms(q + dq, after);
    for (const CollisionElement& element : world.elements())
    {
      // Farthest point of the element: its origin plus bounding radius in the worst direction.
      const Eigen::Isometry3d a = before[element.body] * element.local, b = after[element.body] * element.local;
      const double rotation = rotationError(b.linear(), a.linear()).norm();
      EXPECT_LE((b.translation() - a.translation()).norm() + rotation * element.bounding_radius, bound + 1e-12);
    }
  }
}

TEST(StateChecker, OtherRobotStateIsFrozenObstacle)
{
  CollisionWorld world(fixture("ur5e.urdf"), { ball("ball", Eigen::Vector3d(0, 0, 0.3), 0.1) });
  world.computeAllowedCollisions(300, 1);
  // The ball sits in the shoulder, which the wrist cannot move: a frozen contact is not the group's.
  StateChecker wrist_only(world, { "wrist_3_joint" }, Eigen::VectorXd::Zero(6));
  EXPECT_TRUE(wrist_only.valid(Eigen::VectorXd::Zero(1)));
  EXPECT_TRUE(world.check(Eigen::VectorXd::Zero(6)).collision);
  StateChecker arm(world, kJoints, Eigen::VectorXd::Zero(6));
  EXPECT_FALSE(arm.valid(Eigen::VectorXd::Zero(6)));
  EXPECT_GT(arm.pairCount(), wrist_only.pairCount());
  EXPECT_EQ(wrist_only.size(), 1u);
  EXPECT_THROW(StateChecker(world, std::vector<std::string>{ "no_joint" }, Eigen::VectorXd::Zero(6)), KinematicsError);
  EXPECT_THROW(StateChecker(world, kJoints, Eigen::VectorXd::Zero(3)), KinematicsError);
}
