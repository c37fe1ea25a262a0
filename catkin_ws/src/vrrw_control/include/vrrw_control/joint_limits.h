#pragma once
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace vrrw_control
{
/// \brief Limits of one joint: URDF position/velocity limits plus the acceleration limit of its robot config.
struct JointLimits
{
  std::string name;
  bool has_position_limits = false;  ///< false for continuous joints
  double min_position = -std::numeric_limits<double>::infinity();
  double max_position = std::numeric_limits<double>::infinity();
  double max_velocity = std::numeric_limits<double>::infinity();
  double max_acceleration = std::numeric_limits<double>::infinity();
};

/// \brief Limits of the named joints from a URDF, with max_acceleration from `acceleration_limits` (prefixed joint
/// names, as vrrw_scene::Robot::acceleration_limits; a joint without one stays unlimited); throws
/// std::runtime_error naming a missing joint.
std::vector<JointLimits> loadJointLimits(const std::string& urdf_xml, const std::vector<std::string>& joints,
                                         const std::map<std::string, double>& acceleration_limits = {});
}  // namespace vrrw_control
