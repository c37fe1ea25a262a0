#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "scene_fixtures.h"
#include "vrrw_kinematics/collision_world.h"
#include "vrrw_kinematics/kinematics_error.h"

using namespace vrrw_kinematics;

TEST(CollisionWorld, BodiesFromUrdfAndObjects)
{
  const CollisionWorld world(fixture("ur5e.urdf"), { ball("ball", Eigen::Vector3d(0, 0, 0.5), 0.1) });
  EXPECT_EQ(world.bodies().size(), 8u);
  EXPECT_GE(world.bodyIndex("ball"), 0);
  EXPECT_EQ(world.bodyIndex("tool0"), -1);
  EXPECT_THROW(CollisionWorld(fixture("ur5e.urdf"), { ball("shoulder_link", Eigen::Vector3d::Zero(), 0.1) }),
               KinematicsError);
}

TEST(CollisionWorld, SeparatedAndTouchingBall)
{
  CollisionWorld world(fixture("ur5e.urdf"), { ball("ball", Eigen::Vector3d(0, 0, 0.5), 0.1) });
  world.computeAllowedCollisions(500, 1);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
  EXPECT_FALSE(world.check(zero).collision);
  // Shoulder cylinder top at 0.1625 + 0.075 = 0.2375; ball bottom at 0.4.
  const DistanceReport report = world.distance(zero, "ball");
  EXPECT_NEAR(report.distance, 0.1625, 1e-6);
  EXPECT_EQ(report.body_a == "ball" ? report.body_b : report.body_a, "shoulder_link");

  world.setObjectPose("ball", Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.3)));
  const Contact contact = world.check(zero);
  ASSERT_TRUE(contact.collision);
  EXPECT_TRUE((contact.body_a == "ball" && contact.body_b == "shoulder_link") ||
              (contact.body_b == "ball" && contact.body_a == "shoulder_link"));
  // overlapping shapes: FCL's distance query answers -1, not a depth (the ball is 3.75 cm into the shoulder)
  EXPECT_EQ(world.distance(zero, "ball").distance, -1.0);
  EXPECT_EQ(world.distance(zero).distance, -1.0);
  EXPECT_THROW(world.distance(zero, "nothing"), KinematicsError);
  EXPECT_LE(world.distance(zero, "ur5e").distance, 0.0);  // the URDF's robot name owns every link
}

TEST(CollisionWorld, AutomaticMatrixAllowsAdjacentAndNeverPairs)
{
  CollisionWorld world(fixture("ur5e.urdf"), { slab("floor", Eigen::Vector3d(0, 0, -0.04), Eigen::Vector3d(2, 2, 0.1)) });
  world.computeAllowedCollisions(2000, 3);
  const AllowedCollisionMatrix& acm = world.acm();
  EXPECT_EQ(acm.reason("shoulder_link", "upper_arm_link"), "adjacent");
  EXPECT_EQ(acm.reason("base_link_inertia", "shoulder_link"), "adjacent");
  EXPECT_EQ(acm.reason("wrist_2_link", "wrist_3_link"), "adjacent");
  EXPECT_EQ(acm.reason("base_link_inertia", "floor"), "always");
  EXPECT_EQ(acm.reason("base_link_inertia", "wrist_3_link"), "");
  EXPECT_GE(acm.count("adjacent"), 6u);
  // Links at most two joints apart are sampled densely; the rest can all come within 2 cm of each other.
  EXPECT_EQ(acm.reason("wrist_1_link", "wrist_3_link"), "never");
  EXPECT_EQ(acm.reason("forearm_link", "wrist_2_link"), "never");
  EXPECT_EQ(acm.reason("base_link_inertia", "upper_arm_link"), "never");
  EXPECT_EQ(acm.count("never"), 3u);
  EXPECT_FALSE(acm.allowed("forearm_link", "floor"));
}

TEST(CollisionWorld, SelfCollisionWhenFolded)
{
  CollisionWorld world(fixture("ur5e.urdf"));
  world.computeAllowedCollisions(2000, 3);
  Eigen::VectorXd folded = Eigen::VectorXd::Zero(6);
  folded[2] = 3.1;
  const Contact contact = world.check(folded);
  ASSERT_TRUE(contact.collision);
  EXPECT_EQ(world.acm().reason(contact.body_a, contact.body_b), "");
  EXPECT_FALSE(world.check(Eigen::VectorXd::Zero(6)).collision);
}

TEST(CollisionWorld, CacheRoundTripAndKey)
{
  const std::string dir = "/tmp/vrrw_acm_cache_" + std::to_string(::getpid());
  CollisionWorld first(fixture("ur5e.urdf"));
  EXPECT_FALSE(first.loadOrComputeAllowedCollisions(dir, 300, 2));
  CollisionWorld second(fixture("ur5e.urdf"));
  EXPECT_TRUE(second.loadOrComputeAllowedCollisions(dir, 300, 2));
  EXPECT_EQ(first.acm().entries(), second.acm().entries());
  EXPECT_NE(first.contentKey(300, 2), first.contentKey(300, 3));
  std::system(("rm -rf " + dir).c_str());
}

TEST(CollisionWorld, AttachedObjectMovesWithTheLink)
{
  CollisionWorld world(fixture("ur5e.urdf"), { ball("tool", Eigen::Vector3d(0.8172, 0.2829, 0.0628), 0.03) });
  world.computeAllowedCollisions(300, 1);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
  world.attachObject("tool", "wrist_3_link", zero, { "wrist_2_link" });
  EXPECT_EQ(world.acm().reason("tool", "wrist_3_link"), "attached");
  Eigen::VectorXd q = zero;
  q[0] = M_PI / 2;
  std::vector<Eigen::Isometry3d> poses;
  world.bodyTransforms(q, poses);
  const Eigen::Vector3d moved = poses[world.bodyIndex("tool")].translation();
  EXPECT_NEAR(moved.x(), -0.2829, 1e-9);
  EXPECT_NEAR(moved.y(), 0.8172, 1e-9);
  world.detachObject("tool", q);
  EXPECT_EQ(world.acm().reason("tool", "wrist_3_link"), "");
  world.bodyTransforms(zero, poses);
  EXPECT_NEAR(poses[world.bodyIndex("tool")].translation().y(), 0.8172, 1e-9);
  EXPECT_THROW(world.detachObject("tool", q), KinematicsError);
  EXPECT_THROW(world.setObjectPose("nothing", Eigen::Isometry3d::Identity()), KinematicsError);
}
