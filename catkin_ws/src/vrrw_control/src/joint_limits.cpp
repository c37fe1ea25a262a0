#include <stdexcept>
#include <urdf_parser/urdf_parser.h>
#include <vrrw_control/joint_limits.h>
#include <yaml-cpp/yaml.h>

namespace vrrw_control
{
std::vector<JointLimits> loadJointLimits(const std::string& urdf_xml, const std::vector<std::string>& joints)
{
  const auto model = urdf::parseURDF(urdf_xml);
  if (!model)
    throw std::runtime_error("robot_description: not a valid URDF");
  std::vector<JointLimits> result;
  for (const auto& name : joints)
  {
    const auto joint = model->getJoint(name);
    if (!joint)
      throw std::runtime_error("robot_description: joint " + name + ": not in the URDF");
    JointLimits l;
    l.name = name;
    if (joint->limits)
    {
      if (joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::PRISMATIC)
      {
        l.has_position_limits = true;
        l.min_position = joint->limits->lower;
        l.max_position = joint->limits->upper;
      }
      if (joint->limits->velocity > 0.0)
        l.max_velocity = joint->limits->velocity;
    }
    result.push_back(l);
  }
  return result;
}

void loadAccelerationLimits(const std::string& yaml_path, const std::string& prefix, std::vector<JointLimits>& limits)
{
  YAML::Node root;
  try
  {
    root = YAML::LoadFile(yaml_path);
  }
  catch (const YAML::Exception& e)
  {
    throw std::runtime_error(yaml_path + ": " + e.what());
  }
  const auto acc = root["acceleration_limits"];
  if (!acc)
    return;
  if (!acc.IsMap())
    throw std::runtime_error(yaml_path + ": acceleration_limits: expected a map joint -> rad/s^2");
  for (auto& l : limits)
  {
    const std::string key = l.name.rfind(prefix, 0) == 0 ? l.name.substr(prefix.size()) : l.name;
    if (!acc[key])
      continue;
    double value = 0.0;
    try
    {
      value = acc[key].as<double>();
    }
    catch (const YAML::Exception&)
    {
      throw std::runtime_error(yaml_path + ": acceleration_limits." + key + ": not a number");
    }
    if (!(value > 0.0))
      throw std::runtime_error(yaml_path + ": acceleration_limits." + key + ": must be positive");
    l.max_acceleration = value;
  }
}
}  // namespace vrrw_control
