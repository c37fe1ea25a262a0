#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <vrrw_control/joint_limits.h>
#include <vrrw_scene/robot_config.h>

namespace
{
std::string readFile(const std::string& path)
{
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}
}  // namespace

TEST(JointLimits, FromUrdfAndYaml)
{
  auto limits = vrrw_control::loadJointLimits(readFile("data/ur5e_fixture.urdf"),
                                              { "ur5e_elbow_joint", "ur5e_shoulder_pan_joint" });
  ASSERT_EQ(limits.size(), 2u);
  EXPECT_EQ(limits[0].name, "ur5e_elbow_joint");
  EXPECT_NEAR(limits[0].max_position, 3.141592653589793, 1e-12);
  EXPECT_NEAR(limits[0].max_velocity, 3.14159, 1e-12);
  EXPECT_TRUE(std::isinf(limits[0].max_acceleration));
  limits = vrrw_control::loadJointLimits(readFile("data/ur5e_fixture.urdf"),
                                         { "ur5e_elbow_joint", "ur5e_shoulder_pan_joint" },
                                         vrrw_scene::loadAccelerationLimits("data/ur5e.yaml", "ur5e_"));
  EXPECT_EQ(limits[0].max_acceleration, 8.0);
  EXPECT_EQ(limits[1].max_acceleration, 8.0);
}

TEST(JointLimits, MissingJointIsNamed)
{
  try
  {
    vrrw_control::loadJointLimits(readFile("data/ur5e_fixture.urdf"), { "ur5e_nope_joint" });
    FAIL();
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("ur5e_nope_joint"), std::string::npos);
  }
}

TEST(JointLimits, JointWithoutAccelerationLimitStaysUnlimited)
{
  const auto limits = vrrw_control::loadJointLimits(readFile("data/ur5e_fixture.urdf"),
                                                    { "ur5e_elbow_joint", "ur5e_wrist_1_joint" },
                                                    { { "ur5e_elbow_joint", 2.5 } });
  EXPECT_EQ(limits[0].max_acceleration, 2.5);
  EXPECT_TRUE(std::isinf(limits[1].max_acceleration));
}

TEST(JointLimits, BadYamlIsNamed)
{
  try
  {
    vrrw_scene::loadAccelerationLimits("data/missing.yaml", "ur5e_");
    FAIL();
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("data/missing.yaml"), std::string::npos) << e.what();
  }
}
