#include "vrrw_kinematics/ik_solver.h"

#include <cmath>

namespace vrrw_kinematics
{
IkSolver::IkSolver(const KinematicChain& chain)
  : chain_(chain), analytic_(URAnalyticIK::detect(chain)), numeric_(chain)
{
}

std::string invalidPoseReason(const Eigen::Isometry3d& pose)
{
  if (!pose.matrix().allFinite())
    return "pose contains NaN or infinity";
  const Eigen::Matrix3d r = pose.linear();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 || r.determinant() < 0.0)
    return "pose orientation is not a rotation";
  return "";
}

Eigen::Isometry3d poseFromQuaternion(const Eigen::Vector3d& position, const Eigen::Vector4d& xyzw, double tolerance)
{
  if (!position.allFinite() || !xyzw.allFinite())
    throw KinematicsError(ErrorCode::InvalidPose, "pose: NaN or infinite value");
  if (std::abs(xyzw.norm() - 1.0) > tolerance)
    throw KinematicsError(ErrorCode::InvalidPose,
                          "pose: quaternion norm " + std::to_string(xyzw.norm()) + " is not 1");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position;
  pose.linear() = Eigen::Quaterniond(xyzw[3], xyzw[0], xyzw[1], xyzw[2]).normalized().toRotationMatrix();
  return pose;
}

IkResult IkSolver::solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options) const
{
  IkResult result;
  const std::string reason = invalidPoseReason(target);
  if (!reason.empty())
  {
    result.code = ErrorCode::InvalidPose;
    result.message = "IK target for " + chain_.tipLink() + ": " + reason;
    return result;
  }
  if (static_cast<std::size_t>(seed.size()) != chain_.size() || !seed.allFinite())
  {
    result.code = ErrorCode::InvalidArgument;
    result.message = "IK seed: expected " + std::to_string(chain_.size()) + " finite joint values, got " +
                     std::to_string(seed.size());
    return result;
  }
  if (analytic_ && options.allow_analytic && options.mode == IkOptions::Mode::Full)
  {
    result.attempts = 1;
    if (analytic_->solveNearest(target, seed, result.q))
    {
      const Eigen::Isometry3d reached = chain_.fk(result.q);
      result.position_error = (reached.translation() - target.translation()).norm();
      result.orientation_error = rotationError(target.linear(), reached.linear()).norm();
      if (result.position_error <= options.tolerance && result.orientation_error <= options.tolerance)
      {
        result.success = true;
        result.code = ErrorCode::Ok;
        return result;
      }
      // Near a wrist singularity the closed form loses digits: polish with Newton steps from it.
      return numeric_.solve(target, result.q, options);
    }
    result.code = ErrorCode::NoSolution;
    result.message = "no IK solution for tip " + chain_.tipLink() + ": pose unreachable within joint limits";
    return result;
  }
  return numeric_.solve(target, seed, options);
}

std::vector<Eigen::VectorXd> IkSolver::solveAll(const Eigen::Isometry3d& target, const Eigen::VectorXd& reference) const
{
  if (!analytic_ || !invalidPoseReason(target).empty())
    return {};
  return analytic_->solveAll(target, reference);
}
}  // namespace vrrw_kinematics
