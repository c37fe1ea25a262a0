#include <yaml-cpp/yaml.h>

#include "vrrw_kinematics/kinematics_error.h"
#include "vrrw_kinematics/time_parameterization.h"

namespace vrrw_kinematics
{
std::vector<double> loadAccelerationLimits(const std::string& yaml_path, const std::vector<std::string>& joint_names,
                                           const std::string& prefix)
{
  YAML::Node root;
  try
  {
    root = YAML::LoadFile(yaml_path);
  }
  catch (const std::exception& e)
  {
    throw KinematicsError(ErrorCode::InvalidArgument, yaml_path + ": cannot be read (" + e.what() + ")");
  }
  const YAML::Node limits = root["acceleration_limits"];
  if (!limits || !limits.IsMap())
    throw KinematicsError(ErrorCode::InvalidArgument, yaml_path + ": acceleration_limits: missing");
  std::vector<double> out;
  for (const std::string& joint : joint_names)
  {
    const std::string name = joint.compare(0, prefix.size(), prefix) == 0 ? joint.substr(prefix.size()) : joint;
    const YAML::Node value = limits[name];
    double limit = 0.0;
    try
    {
      limit = value ? value.as<double>() : 0.0;
    }
    catch (const std::exception&)
    {
      limit = 0.0;
    }
    if (!(limit > 0.0))
      throw KinematicsError(ErrorCode::InvalidArgument,
                            yaml_path + ": acceleration_limits: " + name + ": missing or not a positive number");
    out.push_back(limit);
  }
  return out;
}
}  // namespace vrrw_kinematics
