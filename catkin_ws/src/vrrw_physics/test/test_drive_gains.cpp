#include <vrrw_physics/drive_gains.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using namespace vrrw_physics;

namespace
{
std::string writeFile(const std::string& name, const std::string& text)
{
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}
}  // namespace

TEST(DriveGains, ReadsModelDefaultsAndJointOverrides)
{
  const std::string path = writeFile("gains_ok.yaml", R"(
model: test
acceleration_limits: {a: 1.0}
drives:
  rigid: {stiffness: 2.0e5, damping: 9.0e4, max_force: 150}
  compliant: {stiffness: 0.0, damping: 12.0}
  elbow_joint: {rigid: {stiffness: 3.0e5}, compliant: {damping: 5.0}}
)");
  const DriveGainTable t = loadDriveGains(path);
  EXPECT_DOUBLE_EQ(t.gains("shoulder", DriveMode::Rigid).stiffness, 2e5);
  EXPECT_DOUBLE_EQ(t.gains("shoulder", DriveMode::Rigid).damping, 9e4);
  EXPECT_DOUBLE_EQ(t.gains("shoulder", DriveMode::Rigid).max_force, 150.0);
  EXPECT_DOUBLE_EQ(t.gains("shoulder", DriveMode::Compliant).damping, 12.0);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Rigid).stiffness, 3e5);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Rigid).damping, 9e4);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Compliant).damping, 5.0);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Custom).stiffness, 3e5);
}

TEST(DriveGains, ShippedUr5eConfigHasThePaperGains)
{
  const DriveGainTable t = loadDriveGains(std::string(TEST_DATA) + "/../../../../../urdf/config/ur5e.yaml");
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Rigid).stiffness, 1e5);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Rigid).damping, 8e4);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Compliant).stiffness, 0.0);
  EXPECT_DOUBLE_EQ(t.gains("elbow_joint", DriveMode::Compliant).damping, 30.0);
}

TEST(DriveGains, NegativeOrTextGainsNameTheField)
{
  const std::string negative = writeFile("gains_neg.yaml", "drives:\n  rigid: {stiffness: -1.0}\n");
  try
  {
    loadDriveGains(negative);
    FAIL() << "negative stiffness accepted";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("drives.rigid.stiffness"), std::string::npos) << e.what();
  }
  const std::string text = writeFile("gains_text.yaml", "drives:\n  compliant: {damping: soft}\n");
  EXPECT_THROW(loadDriveGains(text), std::runtime_error);
  EXPECT_THROW(loadDriveGains("/nonexistent/gains.yaml"), std::runtime_error);
}

TEST(DriveGains, ParsesModes)
{
  EXPECT_EQ(parseDriveMode("rigid"), DriveMode::Rigid);
  EXPECT_EQ(parseDriveMode("compliant"), DriveMode::Compliant);
  EXPECT_EQ(parseDriveMode("custom"), DriveMode::Custom);
  EXPECT_THROW(parseDriveMode("floppy"), std::invalid_argument);
}
