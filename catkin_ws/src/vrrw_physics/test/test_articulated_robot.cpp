#include <vrrw_physics/articulated_robot.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <fstream>
#include <sstream>

#include "pendulum_fixture.h"

using namespace vrrw_physics;


TEST(ArticulatedRobot, MergesFixedLinksAndMatchesUrdfKinematics)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  ArticulatedRobot robot(*urdf, "p", "p_base_link");
  ASSERT_EQ(robot.joints().size(), 1u);
  EXPECT_EQ(robot.body()->getNumLinks(), 1);  // p_tip merged into p_arm
  EXPECT_NEAR(robot.body()->getLinkMass(0), 2.0, 1e-12);
  EXPECT_TRUE(robot.joints()[0].limited);
  EXPECT_DOUBLE_EQ(robot.joints()[0].max_effort, 1000.0);
  const double q = 0.3;
  robot.setState({ q }, { 0.0 });
  const Eigen::Isometry3d tip = robot.linkPose("p_tip");
  EXPECT_NEAR((tip.translation() - Eigen::Vector3d(std::cos(q), std::sin(q), 1.1)).norm(), 0.0, 1e-6);
  const Eigen::Matrix3d expected = Eigen::AngleAxisd(q + 1.5708, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_NEAR((tip.rotation() - expected).norm(), 0.0, 1e-6);
  EXPECT_NEAR((robot.linkPose("p_base_link").translation() - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-9);
  EXPECT_FALSE(robot.hasLink("s_carriage"));
}

TEST(ArticulatedRobot, PrismaticJointMovesAlongItsAxis)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  ArticulatedRobot robot(*urdf, "s", "s_base_link");
  robot.setState({ 0.25 }, { 0.0 });
  EXPECT_NEAR((robot.linkPose("s_carriage").translation() - Eigen::Vector3d(3, 0, 0.25)).norm(), 0.0, 1e-6);
  EXPECT_TRUE(robot.joints()[0].prismatic);
}

TEST(ArticulatedRobot, MimicJointGetsACouplingNotADrive)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  ArticulatedRobot robot(*urdf, "g", "g_base_link");
  ASSERT_EQ(robot.joints().size(), 2u);
  EXPECT_EQ(robot.drives().size(), 1u);
  const SimJoint& right = robot.joints()[std::size_t(robot.jointIndex("g_right_joint"))];
  EXPECT_EQ(right.drive, -1);
  EXPECT_EQ(right.mimic, robot.jointIndex("g_left_joint"));
  const auto q = robot.withMimics({ 0.02, 0.0 });
  EXPECT_NEAR(q[std::size_t(robot.jointIndex("g_right_joint"))], -0.02 + 0.01, 1e-12);
}

TEST(ArticulatedRobot, GravityTorqueIsMassTimesLeverArm)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  ArticulatedRobot robot(*urdf, "v", "v_base_link");
  robot.setState({ 0.0 }, { 0.0 });
  // Arm along +x, hinge about +y: gravity's torque about +y is +m g l (pulls x down = positive about y).
  EXPECT_NEAR(robot.gravityTorques(Eigen::Vector3d(0, 0, -9.81))[0], 2.0 * 9.81 * 0.5, 1e-4);
  robot.setState({ 1.0 }, { 0.0 });
  EXPECT_NEAR(robot.gravityTorques(Eigen::Vector3d(0, 0, -9.81))[0], 2.0 * 9.81 * 0.5 * std::cos(1.0), 1e-4);
}

TEST(ArticulatedRobot, UnknownBaseLinkIsNamed)
{
  const auto urdf = vrrw_physics_test::pendulumModel();
  try
  {
    ArticulatedRobot robot(*urdf, "x", "x_base_link");
    FAIL();
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("x_base_link"), std::string::npos);
  }
}
