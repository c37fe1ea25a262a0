#pragma once
#include <Eigen/Geometry>
#include <stdexcept>
#include <string>

namespace vrrw_physics
{
/// \brief Bad input to the world (unknown robot/joint/link, NaN, a value outside its range, wrong lengths);
/// what() is one line naming the thing and, for a number, the range it must lie in. The world is unchanged.
class InputError : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

// The ranges physics accepts. Each is far beyond anything a cell needs and well inside what one float
// (Bullet as packaged) and a 1 ms step can carry.
constexpr double kWorldExtent = 100.0;         ///< m: every coordinate of a robot base, object, spring target, hand
constexpr double kMaxDriveStiffness = 1e7;     ///< N m/rad (N/m): set_gains
constexpr double kMaxDriveDamping = 1e6;       ///< N m s/rad (N s/m): set_gains
constexpr double kMaxDriveForce = 1e5;         ///< N m (N): set_gains max_force, drive target effort
constexpr double kJointLimitMargin = 0.05;     ///< a drive target may pass a joint limit by this share of the range
constexpr double kMaxSpringStiffness = 1e4;    ///< N/m
constexpr double kMaxSpringDamping = 500.0;    ///< N s/m
constexpr double kMaxSpringAngularStiffness = 500.0;  ///< N m/rad
constexpr double kMaxSpringAngularDamping = 50.0;     ///< N m s/rad
constexpr double kMaxSpringForce = 1000.0;     ///< N, and N m for the torque
constexpr double kMaxSpringPointOffset = 2.0;  ///< m: attachment point from its body's frame
constexpr double kMaxTargetSpeed = 10.0;       ///< m/s: a spring target's velocity
constexpr double kMaxHandRadius = 0.25;        ///< m

/// \brief Throws InputError "what: VALUE outside [LOW, HIGH] UNIT" unless low <= value <= high (NaN fails).
void requireInRange(double value, double low, double high, const std::string& what, const std::string& unit);

/// \brief Throws InputError unless the pose is finite, its rotation a rotation and every coordinate of its
/// position within kWorldExtent.
void requireWorkspacePose(const Eigen::Isometry3d& pose, const std::string& what);
}  // namespace vrrw_physics
