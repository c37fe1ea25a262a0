#include <vrrw_physics/drive_gains.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <stdexcept>

namespace vrrw_physics
{
namespace
{
double readNumber(const YAML::Node& node, const std::string& key, double fallback, const std::string& where)
{
  if (!node[key])
    return fallback;
  double value;
  try
  {
    value = node[key].as<double>();
  }
  catch (const YAML::Exception&)
  {
    throw std::runtime_error(where + "." + key + ": not a number");
  }
  if (!std::isfinite(value) || value < 0.0)
    throw std::runtime_error(where + "." + key + ": must be finite and >= 0");
  return value;
}

DriveGains readGains(const YAML::Node& node, const DriveGains& base, const std::string& where)
{
  DriveGains g = base;
  if (!node || !node.IsMap())
    return g;
  g.stiffness = readNumber(node, "stiffness", g.stiffness, where);
  g.damping = readNumber(node, "damping", g.damping, where);
  g.max_force = readNumber(node, "max_effort", g.max_force, where);
  g.max_force = readNumber(node, "max_force", g.max_force, where);
  return g;
}

}  // namespace

DriveMode parseDriveMode(const std::string& text)
{
  if (text == "rigid")
    return DriveMode::Rigid;
  if (text == "compliant")
    return DriveMode::Compliant;
  if (text == "custom")
    return DriveMode::Custom;
  throw std::invalid_argument("mode '" + text + "': expected rigid, compliant or custom");
}

const char* toString(DriveMode mode)
{
  switch (mode)
  {
    case DriveMode::Rigid:
      return "rigid";
    case DriveMode::Compliant:
      return "compliant";
    case DriveMode::Custom:
      return "custom";
  }
  return "?";
}

DriveGains DriveGainTable::gains(const std::string& joint, DriveMode mode) const
{
  const bool compliant_mode = mode == DriveMode::Compliant;
  const auto& table = compliant_mode ? compliant : rigid;
  const auto it = table.find(joint);
  if (it != table.end())
    return it->second;
  return compliant_mode ? default_compliant : default_rigid;
}

DriveGainTable loadDriveGains(const std::string& path)
{
  YAML::Node root;
  try
  {
    root = YAML::LoadFile(path);
  }
  catch (const YAML::Exception& e)
  {
    throw std::runtime_error(path + ": " + e.what());
  }
  DriveGainTable table;
  const YAML::Node drives = root["drives"];
  if (!drives)
    return table;
  if (!drives.IsMap())
    throw std::runtime_error(path + ": drives: expected a map");
  const std::string where = path + ": drives.";
  table.default_rigid = readGains(drives["rigid"], table.default_rigid, where + "rigid");
  table.default_compliant = readGains(drives["compliant"], table.default_compliant, where + "compliant");
  for (const auto& entry : drives)
  {
    const std::string joint = entry.first.as<std::string>();
    if (joint == "rigid" || joint == "compliant")
      continue;
    if (!entry.second.IsMap())
      throw std::runtime_error(where + joint + ": expected a map with rigid and/or compliant");
    table.rigid[joint] = readGains(entry.second["rigid"], table.default_rigid, where + joint + ".rigid");
    table.compliant[joint] = readGains(entry.second["compliant"], table.default_compliant, where + joint + ".compliant");
  }
  return table;
}
}  // namespace vrrw_physics
