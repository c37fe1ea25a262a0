#include "vrrw_scene/robot_config.h"

#include "yaml_field.h"

namespace vrrw_scene
{
std::map<std::string, double> loadAccelerationLimits(const std::string& config_file, const std::string& prefix)
{
  const auto section = YamlField::loadFile(config_file)["acceleration_limits"];
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

double loadFingertipLeverArm(const std::string& gripper_config_file)
{
  const auto field = YamlField::loadFile(gripper_config_file)["fingertip_lever_arm"];
  const double lever_arm = field.asDouble();
  if (!(lever_arm > 0.0))
    field.fail("must be a positive length in m, got " + field.asString());
  return lever_arm;
}
}  // namespace vrrw_scene
