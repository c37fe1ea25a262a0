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
}  // namespace vrrw_scene
