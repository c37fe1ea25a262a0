#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <filesystem>
#include <fstream>

#include "vrrw_scene/robot_config.h"
#include "vrrw_scene/scene_loader.h"

namespace fs = std::filesystem;
using vrrw_scene::LoadOptions;
using vrrw_scene::loadScene;
using vrrw_scene::SceneError;

namespace
{
LoadOptions testOptions()
{
  static const std::string cache = fs::temp_directory_path() / ("vrrw_scene_test_" + std::to_string(getpid()));
  LoadOptions options;
  options.root = VRRW_TEST_ROOT;
  options.cache_dir = cache;
  return options;
}

std::string testFile(const std::string& name)
{
  return std::string(VRRW_TEST_ROOT) + "/test/" + name;
}

/// The one-line message a bad scene gets.
std::string errorOf(const std::string& file)
{
  try
  {
    loadScene(testFile("bad_input/" + file), testOptions());
  }
  catch (const SceneError& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << file << " loaded without an error";
  return "";
}

/// A root whose urdf/config/`config` holds `text`; every other file is the repository's.
LoadOptions rootWithConfig(const std::string& config, const std::string& text)
{
  const fs::path repository = VRRW_TEST_ROOT;
  const fs::path root = fs::temp_directory_path() / ("vrrw_scene_config_" + std::to_string(getpid()) + "_" + config);
  fs::remove_all(root);
  fs::create_directories(root / "urdf" / "config");
  fs::create_symlink(repository / ".venv", root / ".venv");
  for (const auto& entry : fs::directory_iterator(repository / "urdf"))
    if (entry.path().filename() != "config")
      fs::create_symlink(entry.path(), root / "urdf" / entry.path().filename());
  for (const auto& entry : fs::directory_iterator(repository / "urdf" / "config"))
    fs::copy_file(entry.path(), root / "urdf" / "config" / entry.path().filename());
  std::ofstream(root / "urdf" / "config" / config) << text;
  LoadOptions options = testOptions();
  options.root = root.string();
  return options;
}

/// The message pick_place_drill gets under a root whose `config` holds `text`.
std::string configErrorOf(const std::string& config, const std::string& text)
{
  const LoadOptions options = rootWithConfig(config, text);
  std::string message;
  try
  {
    loadScene("pick_place_drill", options);
    ADD_FAILURE() << config << " loaded without an error";
  }
  catch (const SceneError& e)
  {
    message = e.what();
  }
  fs::remove_all(options.root);
  return message;
}

void expectMentions(const std::string& message, std::initializer_list<const char*> parts)
{
  for (const char* part : parts)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing from: " << message;
}
}  // namespace

TEST(BadScene, MalformedYamlNamesFileAndLine)
{
  expectMentions(errorOf("malformed_yaml.yaml"), { "malformed_yaml.yaml:", "malformed YAML" });
}

TEST(BadScene, UnknownModelListsKnownOnes)
{
  expectMentions(errorOf("unknown_model.yaml"), { "unknown_model.yaml:3:", "robots[0].model", "'ur7e'", "ur5e" });
}

TEST(BadScene, UnknownGripper)
{
  expectMentions(errorOf("unknown_gripper.yaml"), { "unknown_gripper.yaml:4:", "robots[0].gripper", "'robotiq_3f'" });
}

TEST(BadScene, DuplicateRobotName)
{
  expectMentions(errorOf("duplicate_name.yaml"), { "duplicate_name.yaml:4:", "robots[1].name", "used twice" });
}

TEST(BadScene, MissingObjectMesh)
{
  expectMentions(errorOf("missing_mesh.yaml"), { "missing_mesh.yaml:4:", "objects[0].mesh", "does not exist" });
}

TEST(BadScene, MissingRobotMesh)
{
  expectMentions(errorOf("missing_mesh_robot.yaml"), { "missing_mesh.urdf", "link 'link2'", "forearm_missing.stl",
                                                       "does not exist" });
}

TEST(BadScene, NonNumericPose)
{
  expectMentions(errorOf("non_numeric_pose.yaml"), { "non_numeric_pose.yaml:4:", "robots[0].base.xyz[1]",
                                                     "expected a number, got 'left'" });
}

TEST(BadScene, JointWithMissingParentLink)
{
  expectMentions(errorOf("bad_parent_link.yaml"), { "bad_parent_link.urdf:5:", "joint 'joint1'",
                                                    "parent link 'link0' does not exist" });
}

/// A robot description no node can use, rejected at scene load with file:line: element: field: reason.
struct BadUrdf
{
  const char* scene;
  std::vector<const char*> message;
};

class BadUrdfScene : public testing::TestWithParam<BadUrdf>
{
};

TEST_P(BadUrdfScene, IsRejectedWithFileLineFieldAndReason)
{
  const std::string message = errorOf(GetParam().scene);
  for (const char* part : GetParam().message)
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' missing from: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    Corpus, BadUrdfScene,
    testing::Values(
        BadUrdf{ "joint_limits_reversed.yaml",
                 { "joint_limits_reversed.urdf:14: joint 'joint1': limit lower: 2 is above the upper limit -2" } },
        BadUrdf{ "zero_velocity.yaml",
                 { "zero_velocity.urdf:18: joint 'joint2': limit velocity: must be greater than zero, got 0" } },
        BadUrdf{ "zero_axis.yaml", { "zero_axis.urdf:14: joint 'joint1': axis xyz: the axis is zero" } },
        BadUrdf{ "custom_robot_without_config.yaml",
                 { "custom_robot_without_config.yaml:2: robots[0].config: missing; a robot with its own description "
                   "needs a config file" } },
        BadUrdf{ "zero_mass.yaml", { "zero_mass.urdf:9: link 'link2': inertial mass: must be greater than zero, got 0" } },
        BadUrdf{ "negative_inertia.yaml",
                 { "negative_inertia.urdf:5: link 'link1': inertial inertia ixx: must not be negative, got -0.01" } },
        BadUrdf{ "inertia_triangle.yaml",
                 { "inertia_triangle.urdf:9: link 'link2': inertial inertia: principal moments 0.005, 0.005, 0.02 "
                   "break the triangle inequality (0.02 > 0.01)" } },
        BadUrdf{ "negative_effort.yaml", { "negative_effort.urdf:14: joint 'joint1': limit effort: -10 outside "
                                           "[0, 1e+06] N m or N (beyond any workspace cell)" } },
        BadUrdf{ "huge_limits.yaml", { "huge_limits.urdf:14: joint 'joint1': limit lower: -1e+300 outside [-100, "
                                       "100] rad or m (beyond any workspace cell)" } },
        BadUrdf{ "huge_mass.yaml", { "huge_mass.urdf:5: link 'link1': inertial mass: 1e+30 outside [0, 10000] kg "
                                     "(beyond any workspace cell)" } }),
    [](const testing::TestParamInfo<BadUrdf>& info) {
      const std::string file = info.param.scene;
      return file.substr(0, file.find('.'));
    });

TEST(BadScene, PlacesAndMassesBeyondAnyCellAreRefused)
{
  EXPECT_EQ(errorOf("far_base.yaml").substr(errorOf("far_base.yaml").find("far_base.yaml")),
            "far_base.yaml:6: robots[0].base.xyz: 1e+30 outside [-100, 100] m (a cell's coordinates)");
  expectMentions(errorOf("far_object.yaml"),
                 { "far_object.yaml:2:", "objects[0].pose.xyz", "-1e+30 outside [-100, 100] m" });
  expectMentions(errorOf("heavy_object.yaml"),
                 { "heavy_object.yaml:4:", "objects[0].mass", "1e+30 outside [0, 10000] kg" });
}

TEST(BadScene, UnknownSceneNameListsShippedScenes)
{
  try
  {
    loadScene("no_such_scene", testOptions());
    FAIL();
  }
  catch (const SceneError& e)
  {
    expectMentions(e.what(), { "no_such_scene", "pick_place_drill" });
  }
}

TEST(BadConfig, MissingAccelerationLimitNamesFileFieldAndJoint)
{
  const std::string ur5e = "acceleration_limits:\n  shoulder_pan_joint: 3.0\n  shoulder_lift_joint: 3.0\n"
                           "  elbow_joint: 3.0\n  wrist_1_joint: 3.0\n  wrist_2_joint: 3.0\n";
  expectMentions(configErrorOf("ur5e.yaml", ur5e),
                 { "config/ur5e.yaml: acceleration_limits.wrist_3_joint: missing", "'ur5e_wrist_3_joint'" });
}

TEST(BadConfig, NonPositiveGripperLimitNamesFileLineAndField)
{
  const std::string robotiq = "model: robotiq_2f_85\nacceleration_limits:\n  finger_joint: 0.0\n";
  expectMentions(configErrorOf("robotiq_2f_85.yaml", robotiq),
                 { "config/robotiq_2f_85.yaml:3: acceleration_limits.finger_joint: must be positive, got 0.0" });
}

TEST(BadConfig, UnreadableConfigIsNamed)
{
  try
  {
    vrrw_scene::loadAccelerationLimits("/nonexistent/ur5e.yaml", "ur5e_");
    FAIL();
  }
  catch (const SceneError& e)
  {
    expectMentions(e.what(), { "/nonexistent/ur5e.yaml: cannot read the file" });
  }
}

TEST(CustomScene, PrefixesEveryNameAndFindsTheChain)
{
  const auto scene = loadScene(testFile("scenes/custom_robot.yaml"), testOptions());
  ASSERT_EQ(scene.robots.size(), 1u);
  const auto& robot = scene.robots[0];
  EXPECT_EQ(robot.base_link, "left_base");
  EXPECT_EQ(robot.tcp_link, "left_tip");
  EXPECT_EQ(robot.arm_joints, (std::vector<std::string>{ "left_joint1", "left_joint2" }));
  EXPECT_DOUBLE_EQ(robot.initial_positions.at("left_joint2"), 0.1);
  EXPECT_DOUBLE_EQ(robot.initial_positions.at("left_joint1"), 0.0);
  EXPECT_DOUBLE_EQ(robot.acceleration_limits.at("left_joint1"), 4.0);  // from its own config
  EXPECT_DOUBLE_EQ(robot.acceleration_limits.at("left_joint2"), 1.5);
  EXPECT_NEAR(robot.base_pose.translation().y(), 0.5, 1e-12);
  EXPECT_NE(scene.urdf.find("name=\"left_base_joint\""), std::string::npos);
  EXPECT_EQ(scene.urdf.find("name=\"joint1\""), std::string::npos);
}

TEST(CustomScene, AXacroPathIsAnArgumentNeverShellText)
{
  // issue 21, bad input 1: xacro ran through popen with the scene author's path inside quotes
  const fs::path folder = fs::temp_directory_path() / ("vrrw_scene_quote_" + std::to_string(getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  const std::string marker = "vrrw_PWNED_" + std::to_string(getpid());  // a shell would make it in our directory
  const std::string hostile = "two_link';touch " + marker + ";'.xacro";
  fs::copy_file(testFile("scenes/two_link.urdf"), folder / hostile);
  fs::copy_file(testFile("scenes/two_link.yaml"), folder / "two_link.yaml");
  std::ofstream(folder / "scene.yaml") << "robots:\n  - name: left\n    description: \"" << hostile
                                       << "\"\n    tip_link: tip\n    config: two_link.yaml\n";
  const auto scene = loadScene((folder / "scene.yaml").string(), testOptions());
  ASSERT_EQ(scene.robots.size(), 1u);
  EXPECT_EQ(scene.robots[0].arm_joints, (std::vector<std::string>{ "left_joint1", "left_joint2" }));
  EXPECT_FALSE(fs::exists(fs::current_path() / marker));
  fs::remove_all(folder);
}

TEST(CustomScene, PrimitiveObjectsHaveBoxAndCylinderInertia)
{
  const auto scene = loadScene(testFile("scenes/custom_robot.yaml"), testOptions());
  const auto* crate = scene.object("crate");
  ASSERT_NE(crate, nullptr);
  EXPECT_DOUBLE_EQ(crate->mass, 2.0);
  EXPECT_NEAR(crate->inertia(0, 0), 2.0 / 12 * (0.04 + 0.01), 1e-12);
  EXPECT_NEAR(crate->inertia(2, 2), 2.0 / 12 * (0.16 + 0.04), 1e-12);
  EXPECT_FALSE(crate->fixed);
  // Seeded random placement: x within 1 +- 0.1, drawn the same on every load.
  EXPECT_GE(crate->pose.translation().x(), 0.9);
  EXPECT_LE(crate->pose.translation().x(), 1.1);
  const auto again = loadScene(testFile("scenes/custom_robot.yaml"), testOptions());
  EXPECT_TRUE(again.object("crate")->pose.isApprox(crate->pose, 0.0));
  EXPECT_TRUE(scene.object("post")->fixed);
}

TEST(ShippedScene, SecondLoadComesFromTheCacheWithTheSameUrdf)
{
  LoadOptions cold = testOptions();
  cold.use_cache = false;
  const auto first = loadScene("pick_place_drill", cold);
  const auto second = loadScene("pick_place_drill", testOptions());
  EXPECT_FALSE(first.from_cache);
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(first.urdf, second.urdf);
  EXPECT_LT(second.load_seconds, first.load_seconds);
}

TEST(ShippedScene, ObjectsAreOutOfTheRobotUrdfAndHaveMass)
{
  const auto scene = loadScene("pick_place_drill", testOptions());
  const auto* drill = scene.object("drill");
  ASSERT_NE(drill, nullptr);
  EXPECT_GT(drill->mass, 1.0);
  EXPECT_LT(drill->mass, 2.5);
  EXPECT_GE(drill->collision.size(), 3u);  // handle, body, battery
  EXPECT_TRUE(scene.object("table")->fixed);
  EXPECT_EQ(scene.urdf.find("drill_"), std::string::npos);
  EXPECT_EQ(scene.urdf.find("table_"), std::string::npos);
  // The inertia is physical: positive definite and obeying the triangle inequality.
  const Eigen::Vector3d principal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(drill->inertia).eigenvalues();
  EXPECT_GT(principal.minCoeff(), 0.0);
  EXPECT_LE(principal.maxCoeff(), principal.sum() - principal.maxCoeff() + 1e-12);
}

TEST(ShippedScene, MultibotRobotsArePrefixedByTheirNames)
{
  const auto scene = loadScene("paper_multibot", testOptions());
  ASSERT_EQ(scene.robots.size(), 4u);
  for (const auto& robot : scene.robots)
  {
    for (const auto& joint : robot.arm_joints)
      EXPECT_EQ(joint.rfind(robot.name + "_", 0), 0u) << joint;
    EXPECT_EQ(robot.tcp_link, robot.name + "_tcp");
    EXPECT_FALSE(robot.gripper_joints.empty()) << robot.name;
  }
  EXPECT_EQ(scene.robot("fetch")->arm_joints.size(), 7u);
  EXPECT_EQ(scene.robot("ur10e")->gripper, "robotiq_2f_140");
}

TEST(ShippedScene, AccelerationLimitsComeFromTheModelAndGripperConfigs)
{
  const auto scene = loadScene("pick_place_drill", testOptions());
  const auto& limits = scene.robot("ur5e")->acceleration_limits;
  EXPECT_EQ(limits.size(), 7u);  // six arm joints and the finger joint; its five mimic joints have none
  EXPECT_DOUBLE_EQ(limits.at("ur5e_shoulder_pan_joint"), 3.14159265);  // urdf/config/ur5e.yaml
  EXPECT_DOUBLE_EQ(limits.at("ur5e_wrist_3_joint"), 3.14159265);
  EXPECT_DOUBLE_EQ(limits.at("ur5e_finger_joint"), 5.0);  // urdf/config/robotiq_2f_85.yaml
}

TEST(ShippedScene, EveryMovableJointOfEveryRobotHasAnAccelerationLimit)
{
  const auto scene = loadScene("paper_multibot", testOptions());
  for (const auto& robot : scene.robots)
  {
    ASSERT_EQ(robot.acceleration_limits.size(), robot.initial_positions.size()) << robot.name;
    for (const auto& joint : robot.initial_positions)
      EXPECT_GT(robot.acceleration_limits.at(joint.first), 0.0) << joint.first;
  }
  const auto& fetch = scene.robot("fetch")->acceleration_limits;  // urdf/config/fetch.yaml
  EXPECT_EQ(fetch.size(), 13u);
  EXPECT_DOUBLE_EQ(fetch.at("fetch_torso_lift_joint"), 0.5);
  EXPECT_DOUBLE_EQ(fetch.at("fetch_wrist_roll_joint"), 2.5);
  EXPECT_DOUBLE_EQ(fetch.at("fetch_l_gripper_finger_joint"), 0.5);
  EXPECT_DOUBLE_EQ(scene.robot("ur10e")->acceleration_limits.at("ur10e_finger_joint"), 5.0);
}
