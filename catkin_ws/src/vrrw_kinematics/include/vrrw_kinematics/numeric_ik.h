#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <random>

#include "vrrw_kinematics/ik_options.h"
#include "vrrw_kinematics/kinematic_chain.h"

namespace vrrw_kinematics
{
/// \brief Numerical IK for any serial chain: damped least squares (Levenberg-Marquardt) Newton steps
/// clamped to the joint limits (joints held at a limit leave the step, an active set), with random
/// restarts until a time limit.
///
/// The search starts from the seed, so the first solution found is normally the nearest one; with
/// IkOptions::nearest it goes on until the timeout and returns the solution nearest the seed.
class NumericIK
{
public:
  explicit NumericIK(const KinematicChain& chain);

  IkResult solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options) const;

private:
  struct Error
  {
    Eigen::Matrix<double, 6, 1> residual;
    double position = 0.0;
    double orientation = 0.0;
  };
  Error error(const Eigen::Isometry3d& target, const Eigen::Isometry3d& current, const IkOptions& options) const;
  bool converged(const Error& e, const IkOptions& options) const;
  bool descend(const Eigen::Isometry3d& target, const IkOptions& options, Eigen::VectorXd& q, Error& e,
               int max_iterations) const;
  void clamp(Eigen::VectorXd& q) const;

  KinematicChain chain_;
  Eigen::VectorXd lower_;
  Eigen::VectorXd upper_;
};
}  // namespace vrrw_kinematics
