#pragma once
#include <map>
#include <string>

namespace vrrw_physics
{
/// \brief Gains of one joint drive: effort = stiffness*(q* - q) - damping*(qd - qd*), |effort| <= max_force.
struct DriveGains
{
  double stiffness = 1e5;  ///< Nm/rad or N/m
  double damping = 8e4;    ///< Nm s/rad or N s/m
  double max_force = 0.0;  ///< Nm or N; 0: the URDF effort limit
};

/// \brief How a robot's arm drives behave.
enum class DriveMode
{
  Rigid,      ///< hold the target with the rigid gains
  Compliant,  ///< stiffness 0, small damping: the arm yields to pushes
  Custom      ///< gains set at run time
};

/// \brief "rigid", "compliant" or "custom"; throws std::invalid_argument otherwise.
DriveMode parseDriveMode(const std::string& text);
const char* toString(DriveMode mode);

/// \brief Rigid and compliant gains of a model: defaults plus per-joint overrides (unprefixed names).
struct DriveGainTable
{
  DriveGains default_rigid{ 1e5, 8e4, 0.0 };   ///< the paper's seed values
  DriveGains default_compliant{ 0.0, 30.0, 0.0 };
  std::map<std::string, DriveGains> rigid;
  std::map<std::string, DriveGains> compliant;

  /// \brief Gains of a joint in a mode (Custom reads as Rigid).
  DriveGains gains(const std::string& joint, DriveMode mode) const;
};

/// \brief Reads drive gains from urdf/config/<model>.yaml:
///   drives:
///     rigid: {stiffness: 1.0e5, damping: 8.0e4, max_force: 150}   # every joint
///     compliant: {stiffness: 0.0, damping: 30.0}
///     elbow_joint: {rigid: {stiffness: 2.0e5}, compliant: {damping: 10.0}}   # optional override
/// Missing keys keep the defaults; other top-level keys (acceleration_limits) are ignored.
/// Throws std::runtime_error "file: drives.field: reason".
DriveGainTable loadDriveGains(const std::string& path);
}  // namespace vrrw_physics
