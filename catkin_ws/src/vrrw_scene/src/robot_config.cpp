#include "vrrw_scene/robot_config.h"

#include <algorithm>

#include "yaml_field.h"

namespace vrrw_scene
{
namespace
{
/// `drives:` of one config file: the gains of every joint it covers, and those of joints it names.
struct DriveSection
{
  JointGains defaults;
  std::map<std::string, JointGains> joints;  ///< unprefixed names
};

std::map<std::string, double> accelerationLimits(const YamlField& config, const std::string& prefix)
{
  const auto section = config["acceleration_limits"];
  section.requireMap();
  std::map<std::string, double> limits;
  for (const auto& joint : section.keys())
  {
    const double limit = section[joint].asDouble();
    if (!(limit > 0.0))
      section[joint].fail("must be positive, got " + section[joint].asString());
    limits[prefix + joint] = limit;
  }
  return limits;
}

DriveGains readGains(const YamlField& field, DriveGains gains)
{
  field.allowKeys({ "stiffness", "damping", "max_force" });
  for (auto [key, value] : { std::pair{ "stiffness", &gains.stiffness }, std::pair{ "damping", &gains.damping },
                             std::pair{ "max_force", &gains.max_force } })
    if (field.has(key))
    {
      *value = field[key].asDouble();
      if (*value < 0.0)
        field[key].fail("must be >= 0, got " + field[key].asString());
    }
  if (gains.stiffness + gains.damping <= 0.0)
    field.fail("stiffness and damping are both 0: the drive would not act");
  return gains;
}

JointGains readModes(const YamlField& field, const JointGains& base, bool only_modes)
{
  if (only_modes)
    field.allowKeys({ "rigid", "compliant" });
  JointGains gains = base;
  if (field.has("rigid"))
    gains.rigid = readGains(field["rigid"], base.rigid);
  if (field.has("compliant"))
    gains.compliant = readGains(field["compliant"], base.compliant);
  return gains;
}

DriveSection readDrives(const YamlField& config, const Robot& robot)
{
  DriveSection section;
  if (!config.has("drives"))
    return section;
  const YamlField drives = config["drives"];
  drives.requireMap();
  section.defaults = readModes(drives, section.defaults, false);
  for (const std::string& joint : drives.keys())
  {
    if (joint == "rigid" || joint == "compliant")
      continue;
    if (!robot.initial_positions.count(robot.name + "_" + joint))
      drives[joint].fail("not a driven joint of robot '" + robot.name + "' (mimic joints follow their master)");
    section.joints[joint] = readModes(drives[joint], section.defaults, true);
  }
  return section;
}
/// An optional positive number of a gripper config (0 when absent).
double optionalPositive(const YamlField& gripper_config, const std::string& key, const std::string& unit)
{
  if (!gripper_config.has(key))
    return 0.0;
  const auto field = gripper_config[key];
  const double value = field.asDouble();
  if (!(value > 0.0))
    field.fail("must be a positive number of " + unit + ", got " + field.asString());
  return value;
}
}  // namespace

std::map<std::string, double> loadAccelerationLimits(const std::string& config_file, const std::string& prefix)
{
  return accelerationLimits(YamlField::loadFile(config_file), prefix);
}

void readRobotConfig(Robot& robot)
{
  robot.acceleration_limits.clear();
  robot.drive_gains.clear();
  for (const auto& entry : robot.initial_positions)
    robot.drive_gains[entry.first] = JointGains();
  if (robot.config_file.empty())
    return;
  const std::string prefix = robot.name + "_";
  const bool gripper_config = !robot.gripper_config_file.empty();
  const YamlField arm = YamlField::loadFile(robot.config_file);
  const YamlField hand = gripper_config ? YamlField::loadFile(robot.gripper_config_file) : arm;
  const auto arm_limits = accelerationLimits(arm, prefix);
  const auto hand_limits = gripper_config ? accelerationLimits(hand, prefix) : arm_limits;
  robot.fingertip_lever_arm = gripper_config ? optionalPositive(hand, "fingertip_lever_arm", "m") : 0.0;
  robot.max_grip_force = gripper_config ? optionalPositive(hand, "max_grip_force", "N") : 0.0;
  const DriveSection arm_drives = readDrives(arm, robot);
  const DriveSection hand_drives = gripper_config ? readDrives(hand, robot) : arm_drives;
  for (const auto& entry : robot.initial_positions)
  {
    const std::string& joint = entry.first;
    const std::string name = joint.substr(prefix.size());
    const bool in_gripper = gripper_config && std::count(robot.gripper_joints.begin(), robot.gripper_joints.end(), joint);
    const auto& limits = in_gripper ? hand_limits : arm_limits;
    const auto limit = limits.find(joint);
    if (limit == limits.end())
      throw SceneError((in_gripper ? robot.gripper_config_file : robot.config_file) + ": acceleration_limits." + name +
                       ": missing for joint '" + joint + "' of robot '" + robot.name + "'");
    robot.acceleration_limits[joint] = limit->second;
    const DriveSection& drives = in_gripper ? hand_drives : arm_drives;
    const auto own = drives.joints.find(name);
    robot.drive_gains[joint] = own == drives.joints.end() ? drives.defaults : own->second;
  }
}
}  // namespace vrrw_scene
