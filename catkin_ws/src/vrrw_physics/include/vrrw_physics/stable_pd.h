#pragma once
#include <vrrw_physics/joint_space_inertia.h>
#include <vector>

namespace vrrw_physics
{
class ArticulatedRobot;

/// \brief Joint drives of one robot solved in joint space, implicitly (stable PD):
/// the drive torque uses the end-of-step velocity x,
///   tau = K*(q* - q - h*x) + D*(qd* - x),
///   (M + h*(h*K + D)) * x = M*qd + h*(K*(q* - q) + D*qd* + tau_external),
/// with M the joint-space inertia (composite rigid body algorithm) reduced onto the non-mimic
/// joints (q = T*q_r, M_r = T'*M*T). Unconditionally stable for K, D >= 0; torques are then
/// clamped to each drive's force limit and applied as joint torques, so Bullet's solver only sees
/// mimic couplings, limits and contacts. Tan, Liu, Turk, "Stable Proportional-Derivative
/// Controllers", IEEE CG&A 2011; Featherstone, "Rigid Body Dynamics Algorithms", ch. 6 (CRBA).
class StablePd
{
public:
  explicit StablePd(const ArticulatedRobot& robot);

  /// \brief Drive torque per joint (0 for mimic joints) for a step of h seconds, given the
  /// joint-space inertia M of the current configuration (jointSpaceInertia()) and the other
  /// generalized forces of the step (gravity, feed-forward), which the prediction of x must include:
  /// without them the static stiffness would fall to K*M/(M + h*(h*K + D)).
  std::vector<double> torques(double h, const JointMatrix& inertia, const std::vector<double>& external) const;

private:
  const ArticulatedRobot& robot_;
  JointMatrix reduction_;  ///< T: joints x driven joints
  std::vector<int> driven_;    ///< joint index of each reduced coordinate
};
}  // namespace vrrw_physics
