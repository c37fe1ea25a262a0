#pragma once
#include <string>

#include <vrrw_scene/scene.h>

namespace vrrw_physics
{
/// \brief Gains of one joint drive (vrrw_scene reads each robot's from its config: Robot::drive_gains).
using DriveGains = vrrw_scene::DriveGains;

/// \brief How a robot's arm drives behave.
enum class DriveMode
{
  Rigid,      ///< hold the target with the rigid gains
  Compliant,  ///< the compliant gains (stiffness 0, small damping): the arm yields to pushes
  Custom      ///< gains set at run time
};

/// \brief "rigid", "compliant" or "custom"; throws std::invalid_argument otherwise.
DriveMode parseDriveMode(const std::string& text);
/// \brief The name parseDriveMode reads.
const char* toString(DriveMode mode);
}  // namespace vrrw_physics
