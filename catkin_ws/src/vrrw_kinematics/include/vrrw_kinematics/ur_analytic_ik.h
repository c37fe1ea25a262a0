#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

#include "vrrw_kinematics/kinematic_chain.h"

namespace vrrw_kinematics
{
/// \brief Denavit-Hartenberg parameters of a UR-type arm (alpha = pi/2, 0, 0, pi/2, -pi/2, 0).
struct URParameters
{
  double d1 = 0.0, a2 = 0.0, a3 = 0.0, d4 = 0.0, d5 = 0.0, d6 = 0.0;
  std::array<double, 6> sign{ { 1, 1, 1, 1, 1, 1 } };    ///< theta_i = sign_i * q_i + offset_i
  std::array<double, 6> offset{ { 0, 0, 0, 0, 0, 0 } };
  Eigen::Isometry3d base_to_dh = Eigen::Isometry3d::Identity();  ///< chain base to DH frame 0
  Eigen::Isometry3d dh_to_tip = Eigen::Isometry3d::Identity();   ///< DH frame 6 to chain tip
};

/// \brief Closed-form IK for the Universal Robots family (all up to 8 solutions).
///
/// K. P. Hawkins, "Analytic Inverse Kinematics for the Universal Robots UR-5/UR-10 Arms", 2013.
/// The DH parameters are extracted from the chain's joint axes at zero, so any URDF of a UR-type arm
/// (any base and tip link, any axis sign convention) is recognised.
class URAnalyticIK
{
public:
  /// \brief The solver when `chain` has the UR structure (checked by FK at random states), else nullopt.
  static std::optional<URAnalyticIK> detect(const KinematicChain& chain);

  const URParameters& parameters() const { return params_; }
  /// \brief Every solution within the joint limits (each joint wrapped by 2 pi nearest `reference`).
  std::vector<Eigen::VectorXd> solveAll(const Eigen::Isometry3d& tip_pose, const Eigen::VectorXd& reference) const;
  /// \brief The solution nearest `seed` (Euclidean in joint space); false when none lies within limits.
  bool solveNearest(const Eigen::Isometry3d& tip_pose, const Eigen::VectorXd& seed, Eigen::VectorXd& q) const;
  /// \brief Tip pose from the DH model (for verification).
  Eigen::Isometry3d fk(const Eigen::VectorXd& q) const;

private:
  URAnalyticIK(const KinematicChain& chain, const URParameters& params);
  int solveDH(const Eigen::Matrix4d& t06, std::array<std::array<double, 6>, 8>& solutions) const;
  bool toJoint(const std::array<double, 6>& theta, const Eigen::VectorXd& reference, Eigen::VectorXd& q) const;

  URParameters params_;
  Eigen::VectorXd lower_;
  Eigen::VectorXd upper_;
};
}  // namespace vrrw_kinematics
