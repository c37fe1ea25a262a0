// robot_config.h: the values a robot's or gripper's urdf/config/<model>.yaml adds to its URDF.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "vrrw_scene/robot_config.h"
#include "vrrw_scene/scene.h"

namespace
{
std::string config(const std::string& name)
{
  return std::string(VRRW_TEST_ROOT) + "/urdf/config/" + name;
}

std::string leverArmErrorOf(const std::string& text)
{
  const auto path = std::filesystem::path(::testing::TempDir()) / "vrrw_gripper_config.yaml";
  std::ofstream(path) << text;
  std::string message = "no error";
  try
  {
    vrrw_scene::loadFingertipLeverArm(path.string());
  }
  catch (const vrrw_scene::SceneError& e)
  {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}
}  // namespace

TEST(FingertipLeverArm, ShippedGrippersMatchTheirUrdfEffortAndRatedForce)
{
  // robotiq_2f.xacro sets the finger_joint effort to the rated grip force times the knuckle length
  EXPECT_NEAR(vrrw_scene::loadFingertipLeverArm(config("robotiq_2f_85.yaml")) * 235.0, 13.4, 0.05);
  EXPECT_NEAR(vrrw_scene::loadFingertipLeverArm(config("robotiq_2f_140.yaml")) * 125.0, 13.6, 0.05);
}

TEST(FingertipLeverArm, MissingOrNonPositiveValueNamesTheField)
{
  EXPECT_NE(leverArmErrorOf("model: g\n").find("vrrw_gripper_config.yaml:1: missing field 'fingertip_lever_arm'"),
            std::string::npos);
  EXPECT_NE(leverArmErrorOf("model: g\nfingertip_lever_arm: -0.05\n")
                .find("vrrw_gripper_config.yaml:2: fingertip_lever_arm: must be a positive length in m, got -0.05"),
            std::string::npos);
}
