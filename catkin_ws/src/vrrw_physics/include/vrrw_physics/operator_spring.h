#pragma once
#include <Eigen/Geometry>
#include <string>

namespace vrrw_physics
{
/// \brief The operator's hand pulling a point of a link or object towards a moving pose
/// (free-drive): a translational and a rotational spring-damper, applied as a wrench each step.
struct OperatorSpring
{
  std::string body;  ///< a robot link or an object name
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< attachment point in the body's frame
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();  ///< in the world
  Eigen::Vector3d target_velocity = Eigen::Vector3d::Zero();
  /// \brief N/m. The default and `damping`'s are the recommended gains for a hand dragging a compliant arm: the
  /// UR5e's wrist follows a target moving 0.2 m/s within 1.3 cm RMS (test_operator_input).
  double stiffness = 5000.0;
  double damping = 100.0;           ///< N s/m
  double angular_stiffness = 0.0;   ///< Nm/rad; 0 leaves orientation free
  double angular_damping = 0.0;     ///< Nm s/rad
  double max_force = 200.0;         ///< N, and Nm for the torque

  /// \brief Force at the attachment point from its world position and velocity.
  Eigen::Vector3d force(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) const;
  /// \brief Torque on the body from its world orientation and angular velocity.
  Eigen::Vector3d torque(const Eigen::Matrix3d& orientation, const Eigen::Vector3d& angular_velocity) const;
};
}  // namespace vrrw_physics
