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

/// \brief `fingertip_lever_arm` (m) of a gripper's urdf/config/<gripper>.yaml: from the actuated joint's
/// axis to the fingertip, so a fingertip force F (GripperCommand max_effort) is a joint torque F x lever arm.
///
/// Throws SceneError "file:line: fingertip_lever_arm: reason" for an unreadable file, a missing field
/// or a value that is not a positive number.
double loadFingertipLeverArm(const std::string& gripper_config_file);
}  // namespace vrrw_scene
