#include <gtest/gtest.h>

#include "fixtures.h"
#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/robot_model.h"

using namespace vrrw_kinematics;

namespace
{
const char* kMimicUrdf = R"(<robot name="m">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" type="prismatic"><parent link="a"/><child link="b"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.04" effort="1" velocity="0.1"/></joint>
  <joint name="j2" type="prismatic"><parent link="a"/><child link="c"/><axis xyz="0 1 0"/>
    <limit lower="-0.04" upper="0" effort="1" velocity="0.1"/><mimic joint="j1" multiplier="-1" offset="0"/></joint>
</robot>)";
}

TEST(RobotModel, LoadsUr5eTree)
{
  const RobotModel model = RobotModel::fromUrdf(fixture("ur5e.urdf"));
  EXPECT_EQ(model.links().size(), 10u);
  EXPECT_EQ(model.variableCount(), 6u);
  EXPECT_EQ(model.variableNames()[0], "shoulder_pan_joint");
  EXPECT_EQ(model.links()[0].name, "base_link");
  EXPECT_EQ(model.links()[model.linkIndex("upper_arm_link")].collision.size(), 1u);
  EXPECT_NEAR(model.links()[model.linkIndex("upper_arm_link")].collision[0].length, 0.5, 1e-12);
  EXPECT_TRUE(model.isDescendant(model.linkIndex("tool0"), model.linkIndex("shoulder_link")));
  EXPECT_FALSE(model.isDescendant(model.linkIndex("shoulder_link"), model.linkIndex("tool0")));
}

TEST(RobotModel, MimicJointFollowsItsVariable)
{
  const RobotModel model = RobotModel::fromUrdf(kMimicUrdf);
  ASSERT_EQ(model.variableCount(), 1u);
  Eigen::VectorXd q(1);
  q << 0.03;
  EXPECT_NEAR(model.relativeTransform(q, "a", "c").translation().y(), -0.03, 1e-15);
  EXPECT_NEAR(model.relativeTransform(q, "b", "c").translation().y(), -0.06, 1e-15);
}

TEST(RobotModel, BadInputNamesTheProblem)
{
  try
  {
    RobotModel::fromUrdf("<robot name='x'><link name='a'/><joint name='j'");
    FAIL();
  }
  catch (const KinematicsError& e)
  {
    EXPECT_EQ(e.code(), ErrorCode::InvalidUrdf);
  }
  const RobotModel model = RobotModel::fromUrdf(fixture("ur5e.urdf"));
  try
  {
    model.linkIndex("no_such_link");
    FAIL();
  }
  catch (const KinematicsError& e)
  {
    EXPECT_EQ(e.code(), ErrorCode::UnknownLink);
    EXPECT_NE(std::string(e.what()).find("no_such_link"), std::string::npos);
  }
}
