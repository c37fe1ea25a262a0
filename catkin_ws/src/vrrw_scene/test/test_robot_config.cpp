// readRobotConfig: acceleration limits and drive gains of urdf/config/<model>.yaml, read once for everyone.
#include <gtest/gtest.h>

#include <fstream>

#include "vrrw_scene/robot_config.h"

using vrrw_scene::readRobotConfig;
using vrrw_scene::Robot;
using vrrw_scene::SceneError;

namespace
{
std::string writeFile(const std::string& name, const std::string& text)
{
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

/// A two-joint arm `arm` (shoulder, elbow) with a one-joint gripper (finger) whose config is `gripper_config`.
Robot robotWith(const std::string& config, const std::string& gripper_config = "")
{
  Robot robot;
  robot.name = "arm";
  robot.initial_positions = { { "arm_shoulder", 0.0 }, { "arm_elbow", 0.0 }, { "arm_finger", 0.0 } };
  robot.gripper_joints = { "arm_finger" };
  robot.config_file = writeFile("arm.yaml", config);
  if (!gripper_config.empty())
    robot.gripper_config_file = writeFile("gripper.yaml", gripper_config);
  return robot;
}

std::string errorOf(Robot robot)
{
  try
  {
    readRobotConfig(robot);
  }
  catch (const SceneError& e)
  {
    return e.what();
  }
  ADD_FAILURE() << "no SceneError";
  return "";
}

const char* kLimits = "acceleration_limits: {shoulder: 1.0, elbow: 2.0, finger: 3.0}\n";
}  // namespace

TEST(RobotConfig, ReadsDefaultsJointOverridesAndTheGrippersOwnFile)
{
  Robot robot = robotWith(std::string(kLimits) + R"(drives:
  rigid: {stiffness: 2.0e5, damping: 9.0e4, max_force: 150}
  compliant: {damping: 12.0}
  elbow: {rigid: {stiffness: 3.0e5}, compliant: {damping: 5.0}}
)",
                          "acceleration_limits: {finger: 5.0}\ndrives:\n  rigid: {stiffness: 1.0e4, damping: 100}\n");
  readRobotConfig(robot);
  const auto& shoulder = robot.drive_gains.at("arm_shoulder");
  EXPECT_DOUBLE_EQ(shoulder.rigid.stiffness, 2e5);
  EXPECT_DOUBLE_EQ(shoulder.rigid.damping, 9e4);
  EXPECT_DOUBLE_EQ(shoulder.rigid.max_force, 150.0);
  EXPECT_DOUBLE_EQ(shoulder.compliant.stiffness, 0.0);  // the default, kept
  EXPECT_DOUBLE_EQ(shoulder.compliant.damping, 12.0);
  const auto& elbow = robot.drive_gains.at("arm_elbow");
  EXPECT_DOUBLE_EQ(elbow.rigid.stiffness, 3e5);
  EXPECT_DOUBLE_EQ(elbow.rigid.damping, 9e4);  // from the file's rigid defaults
  EXPECT_DOUBLE_EQ(elbow.compliant.damping, 5.0);
  const auto& finger = robot.drive_gains.at("arm_finger");  // from the gripper's file
  EXPECT_DOUBLE_EQ(finger.rigid.stiffness, 1e4);
  EXPECT_DOUBLE_EQ(finger.rigid.damping, 100.0);
  EXPECT_DOUBLE_EQ(robot.acceleration_limits.at("arm_finger"), 5.0);
  EXPECT_DOUBLE_EQ(robot.acceleration_limits.at("arm_elbow"), 2.0);
}

TEST(RobotConfig, NoDrivesSectionOrNoConfigGivesThePapersGains)
{
  Robot robot = robotWith(kLimits);
  readRobotConfig(robot);
  EXPECT_DOUBLE_EQ(robot.drive_gains.at("arm_finger").rigid.stiffness, 1e5);
  EXPECT_DOUBLE_EQ(robot.drive_gains.at("arm_finger").rigid.damping, 8e4);
  EXPECT_DOUBLE_EQ(robot.drive_gains.at("arm_shoulder").compliant.damping, 30.0);
  robot.config_file.clear();
  readRobotConfig(robot);
  EXPECT_TRUE(robot.acceleration_limits.empty());
  EXPECT_EQ(robot.drive_gains.size(), 3u);
  EXPECT_DOUBLE_EQ(robot.drive_gains.at("arm_elbow").rigid.stiffness, 1e5);
}

TEST(RobotConfig, BadGainsNameFileLineAndField)
{
  EXPECT_NE(errorOf(robotWith(std::string(kLimits) + "drives:\n  rigid: {stiffness: -1.0}\n"))
                .find("arm.yaml:3: drives.rigid.stiffness: must be >= 0, got -1.0"),
            std::string::npos);
  EXPECT_NE(errorOf(robotWith(std::string(kLimits) + "drives:\n  compliant: {damping: soft}\n"))
                .find("drives.compliant.damping: expected a number, got 'soft'"),
            std::string::npos);
  EXPECT_NE(errorOf(robotWith(std::string(kLimits) + "drives:\n  compliant: {stiffness: 0, damping: 0}\n"))
                .find("drives.compliant: stiffness and damping are both 0"),
            std::string::npos);
  EXPECT_NE(errorOf(robotWith(std::string(kLimits) + "drives:\n  rigid: {stifness: 1.0}\n"))
                .find("drives.rigid.stifness: unknown field"),
            std::string::npos);
  EXPECT_NE(errorOf(robotWith(std::string(kLimits) + "drives:\n  elbw: {rigid: {damping: 1.0}}\n"))
                .find("drives.elbw: not a driven joint of robot 'arm'"),
            std::string::npos);
  EXPECT_NE(errorOf(robotWith("acceleration_limits: {shoulder: 1.0, finger: 3.0}\n"))
                .find("acceleration_limits.elbow: missing for joint 'arm_elbow'"),
            std::string::npos);
}

TEST(RobotConfig, TheGrippersLeverArmComesFromItsOwnFile)
{
  Robot robot = robotWith(kLimits, "acceleration_limits: {finger: 5.0}\nfingertip_lever_arm: 0.057\n");
  readRobotConfig(robot);
  EXPECT_DOUBLE_EQ(robot.fingertip_lever_arm, 0.057);
  EXPECT_NE(errorOf(robotWith(kLimits, "acceleration_limits: {finger: 5.0}\nfingertip_lever_arm: -0.05\n"))
                .find("gripper.yaml:2: fingertip_lever_arm: must be a positive number of m, got -0.05"),
            std::string::npos);
}

TEST(RobotConfig, ShippedGrippersGiveTheirLeverArmAndRatedForce)
{
  for (const auto& [gripper, force] : { std::pair{ "robotiq_2f_85", 235.0 }, std::pair{ "robotiq_2f_140", 125.0 } })
  {
    Robot robot = robotWith(kLimits);
    robot.gripper_config_file = std::string(VRRW_SCENE_ROOT) + "/urdf/config/" + gripper + ".yaml";
    robot.initial_positions = { { "arm_shoulder", 0.0 }, { "arm_elbow", 0.0 }, { "arm_finger_joint", 0.0 } };
    robot.gripper_joints = { "arm_finger_joint" };
    readRobotConfig(robot);
    EXPECT_GT(robot.fingertip_lever_arm, 0.0) << gripper;
    EXPECT_DOUBLE_EQ(robot.max_grip_force, force) << gripper;
  }
}
