#pragma once
#include <map>
#include <string>

#include "vrrw_scene/scene.h"

namespace vrrw_scene
{
/// \brief `acceleration_limits: {joint: value}` of a urdf/config/<model>.yaml, keyed by `prefix + joint`.
///
/// Throws SceneError "file:line: acceleration_limits.joint: reason" for an unreadable file, a missing section
/// or a value that is not a positive number.
std::map<std::string, double> loadAccelerationLimits(const std::string& config_file, const std::string& prefix);
}  // namespace vrrw_scene
