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

/// \brief Fills robot.acceleration_limits and robot.drive_gains for every joint of robot.initial_positions
/// from robot.config_file, gripper joints (and robot.fingertip_lever_arm, robot.max_grip_force) from
/// robot.gripper_config_file when there is one:
///
///     acceleration_limits: {shoulder_pan_joint: 3.14, ...}            # rad/s^2 (m/s^2), every joint
///     drives:                                                          # optional
///       rigid: {stiffness: 1.0e5, damping: 8.0e4, max_force: 150}      # every joint of the file
///       compliant: {stiffness: 0.0, damping: 30.0}
///       elbow_joint: {rigid: {stiffness: 2.0e5}, compliant: {damping: 10.0}}   # one joint
///     fingertip_lever_arm: 0.0182                                      # a gripper's, optional, m
///     max_grip_force: 235.0                                            # a gripper's, optional, N
///
/// Missing gain fields keep JointGains' defaults. A robot without config_file gets the default gains and no
/// acceleration limits. Throws SceneError "file:line: field: reason" (a joint without a limit, a negative or
/// non-numeric gain, stiffness and damping both 0, an unknown field, a drive for a joint the robot does not drive,
/// a lever arm or grip force that is not positive).
void readRobotConfig(Robot& robot);
}  // namespace vrrw_scene
