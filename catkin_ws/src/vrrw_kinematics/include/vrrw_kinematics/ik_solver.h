#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "vrrw_kinematics/ik_options.h"
#include "vrrw_kinematics/kinematic_chain.h"
#include "vrrw_kinematics/numeric_ik.h"
#include "vrrw_kinematics/ur_analytic_ik.h"

namespace vrrw_kinematics
{
/// \brief IK for one chain: the UR closed form when the chain has that structure, else NumericIK.
class IkSolver
{
public:
  explicit IkSolver(const KinematicChain& chain);

  const KinematicChain& chain() const { return chain_; }
  bool hasAnalytic() const { return analytic_.has_value(); }
  /// \brief Solution nearest `seed`; bad input (NaN, non-rotation, wrong seed size) gives code InvalidPose
  /// or InvalidArgument, an unreachable pose NoSolution.
  IkResult solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options = {}) const;
  /// \brief Every closed-form solution within limits (empty when the chain has no closed form).
  std::vector<Eigen::VectorXd> solveAll(const Eigen::Isometry3d& target, const Eigen::VectorXd& reference) const;

private:
  KinematicChain chain_;
  std::optional<URAnalyticIK> analytic_;
  NumericIK numeric_;
};

/// \brief Pose from position and quaternion (x, y, z, w); throws KinematicsError(InvalidPose) on NaN or
/// a quaternion whose norm is not 1 within `tolerance`.
Eigen::Isometry3d poseFromQuaternion(const Eigen::Vector3d& position, const Eigen::Vector4d& xyzw,
                                     double tolerance = 1e-3);
/// \brief Empty when `pose` is a finite rigid transform, else the reason.
std::string invalidPoseReason(const Eigen::Isometry3d& pose);
}  // namespace vrrw_kinematics
