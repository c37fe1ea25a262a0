#include <vrrw_physics/operator_spring.h>

namespace vrrw_physics
{
namespace
{
Eigen::Vector3d clampNorm(const Eigen::Vector3d& v, double limit)
{
  const double n = v.norm();
  return n > limit ? Eigen::Vector3d(v * (limit / n)) : v;
}
}  // namespace

Eigen::Vector3d OperatorSpring::force(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) const
{
  return clampNorm(stiffness * (target.translation() - position) - damping * (velocity - target_velocity), max_force);
}

Eigen::Vector3d OperatorSpring::torque(const Eigen::Matrix3d& orientation, const Eigen::Vector3d& angular_velocity) const
{
  if (angular_stiffness <= 0.0 && angular_damping <= 0.0)
    return Eigen::Vector3d::Zero();
  const Eigen::AngleAxisd error(target.rotation() * orientation.transpose());
  return clampNorm(angular_stiffness * error.angle() * error.axis() - angular_damping * angular_velocity, max_force);
}
}  // namespace vrrw_physics
