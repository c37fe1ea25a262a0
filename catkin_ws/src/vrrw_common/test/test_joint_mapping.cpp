#include <gtest/gtest.h>
#include <vrrw_common/joint_mapping.h>

using vrrw_common::findJoints;
using vrrw_common::inRobotOrder;
using vrrw_common::jointMapping;
using vrrw_common::JointMappingError;

namespace
{
const std::vector<std::string> kRobot = { "pan", "lift", "elbow" };

std::string errorOf(const std::vector<std::string>& given, const std::vector<std::string>& wanted = kRobot)
{
  try
  {
    jointMapping(given, wanted);
  }
  catch (const JointMappingError& e)
  {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(JointMapping, TheCommentsExample)
{
  const std::vector<std::string> given = { "elbow", "pan", "finger", "lift" };
  const auto mapping = jointMapping(given, kRobot);
  EXPECT_EQ(mapping, (std::vector<std::size_t>{ 1, 3, 0 }));
  EXPECT_EQ(inRobotOrder({ 0.3, 0.1, 0.9, 0.2 }, mapping), (std::vector<double>{ 0.1, 0.2, 0.3 }));
  EXPECT_TRUE(inRobotOrder({}, mapping).empty());  // a JointState without velocities
  EXPECT_EQ(findJoints(given, kRobot), mapping);
  EXPECT_EQ(vrrw_common::findValues(given, { 0.3, 0.1, 0.9, 0.2 }, kRobot), (std::vector<double>{ 0.1, 0.2, 0.3 }));
  EXPECT_FALSE(vrrw_common::findValues(given, { 0.3, 0.1, 0.9 }, kRobot));  // lift has no value
  EXPECT_FALSE(vrrw_common::findValues({ "pan", "lift" }, { 0.3, 0.1 }, kRobot));
}

TEST(JointMapping, TheSameOrderMapsToItself)
{
  EXPECT_EQ(jointMapping(kRobot, kRobot), (std::vector<std::size_t>{ 0, 1, 2 }));
  EXPECT_TRUE(jointMapping({ "a" }, {}).empty());
}

TEST(JointMapping, MissingAndDoubledNamesAreRefusedByName)
{
  EXPECT_EQ(errorOf({ "pan", "finger" }), "joint names: missing lift, elbow");
  EXPECT_EQ(errorOf({}), "joint names: missing pan, lift, elbow");
  EXPECT_EQ(errorOf({ "pan", "lift", "elbow", "lift" }), "joint names: lift named twice");
  EXPECT_EQ(errorOf({ "pan", "lift", "elbow" }, { "pan", "pan" }), "joint names: pan named twice");
  EXPECT_EQ(errorOf({ "pan", "lift", "elbow", "finger", "finger" }), "no error");  // not the robot's: skipped
  EXPECT_FALSE(findJoints({ "pan", "finger" }, kRobot));
  EXPECT_FALSE(findJoints({ "pan", "lift", "elbow", "pan" }, kRobot));
}

TEST(JointMapping, AGoalMayNameOnlyTheRobotsJoints)
{
  using vrrw_common::OtherJoints;
  EXPECT_EQ(jointMapping({ "elbow", "pan", "lift" }, kRobot, OtherJoints::Refuse), (std::vector<std::size_t>{ 1, 2, 0 }));
  try
  {
    jointMapping({ "elbow", "pan", "finger", "lift" }, kRobot, OtherJoints::Refuse);
    FAIL() << "no error";
  }
  catch (const JointMappingError& e)
  {
    EXPECT_STREQ(e.what(), "joint names: finger is not a joint of the robot");
    EXPECT_EQ(e.joint(), "finger");
    EXPECT_EQ(e.reason(), "not a joint of the robot");
  }
  try
  {
    jointMapping({ "elbow", "pan" }, kRobot, OtherJoints::Refuse);
    FAIL() << "no error";
  }
  catch (const JointMappingError& e)
  {
    EXPECT_STREQ(e.what(), "joint names: missing lift");
    EXPECT_EQ(e.joint(), "lift");
    EXPECT_EQ(e.reason(), "missing");
  }
}

TEST(JointMapping, APartialGoalMapsEachOfItsJoints)
{
  EXPECT_EQ(vrrw_common::robotIndices({ "elbow", "pan" }, kRobot), (std::vector<std::size_t>{ 2, 0 }));
  EXPECT_TRUE(vrrw_common::robotIndices({}, kRobot).empty());
  try
  {
    vrrw_common::robotIndices({ "elbow", "elbow" }, kRobot);
    FAIL() << "no error";
  }
  catch (const JointMappingError& e)
  {
    EXPECT_STREQ(e.what(), "joint names: elbow named twice");
    EXPECT_EQ(e.reason(), "named twice");
  }
  EXPECT_THROW(vrrw_common::robotIndices({ "wrist" }, kRobot), JointMappingError);
}

TEST(JointMapping, ShortValuesAreRefusedNamingTheField)
{
  const auto mapping = jointMapping({ "elbow", "pan", "lift" }, kRobot);
  try
  {
    inRobotOrder({ 1.0, 2.0 }, mapping, "velocity");
    FAIL() << "no error";
  }
  catch (const JointMappingError& e)
  {
    EXPECT_STREQ(e.what(), "velocity: 2 values, joint 3 of the names has none");
  }
}
