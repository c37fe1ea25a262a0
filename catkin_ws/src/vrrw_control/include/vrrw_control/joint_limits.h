#pragma once
#include <limits>
#include <string>
#include <vector>

namespace vrrw_control
{
/// \brief Limits of one joint: URDF position/velocity limits plus the YAML acceleration limit.
struct JointLimits
{
  std::string name;
  bool has_position_limits = false;  ///< false for continuous joints
  double min_position = -std::numeric_limits<double>::infinity();
  double max_position = std::numeric_limits<double>::infinity();
  double max_velocity = std::numeric_limits<double>::infinity();
  double max_acceleration = std::numeric_limits<double>::infinity();
};

/// \brief Limits of the named joints from a URDF; throws std::runtime_error naming a missing joint.
std::vector<JointLimits> loadJointLimits(const std::string& urdf_xml, const std::vector<std::string>& joints);

/// \brief Applies `acceleration_limits: {unprefixed_joint: value}` of urdf/config/<model>.yaml to joints
/// named `prefix + key`; throws std::runtime_error naming the file and field on bad input.
void loadAccelerationLimits(const std::string& yaml_path, const std::string& prefix, std::vector<JointLimits>& limits);
}  // namespace vrrw_control
