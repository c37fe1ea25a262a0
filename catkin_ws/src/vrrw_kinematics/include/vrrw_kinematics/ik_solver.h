#pragma once
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include <vrrw_kinematics/contact.h>
#include <vrrw_kinematics/ik_options.h>
#include <vrrw_kinematics/kinematic_chain.h>
#include <vrrw_kinematics/numeric_ik.h>
#include <vrrw_kinematics/ur_analytic_ik.h>

namespace vrrw_kinematics
{
/// \brief Collision test of one configuration of a chain: the first pair it touches, or no collision.
using CollisionTest = std::function<Contact(const Eigen::VectorXd& q)>;

/// \brief IK for one chain: the UR closed form when the chain has that structure, else NumericIK.
class IkSolver
{
public:
  explicit IkSolver(const KinematicChain& chain);

  /// \brief The chain base -> tip the solver works on.
  const KinematicChain& chain() const { return chain_; }
  /// \brief True when the chain has the UR structure and is solved in closed form.
  bool hasAnalytic() const { return analytic_.has_value(); }
  /// \brief Solution nearest `seed`; bad input (NaN, non-rotation, wrong seed size) gives code InvalidPose
  /// or InvalidArgument, an unreachable pose NoSolution.
  IkResult solve(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options = {}) const;
  /// \brief Every closed-form solution within limits (empty when the chain has no closed form).
  std::vector<Eigen::VectorXd> solveAll(const Eigen::Isometry3d& target, const Eigen::VectorXd& reference) const;
  /// \brief The solution nearest `seed` (Euclidean) that is within options.max_jump of it on every joint and
  /// that `collides` finds free. Closed form: every solution is tried, nearest first. Numeric: restarts
  /// (within max_jump of the seed when it is finite) until options.timeout. Failure codes: NoSolution
  /// (position_error, orientation_error: the smallest residual reached), JointJump (jump: of the nearest
  /// solution), InCollision (contact: of the nearest solution within max_jump), InvalidPose, InvalidArgument.
  IkResult solveCollisionFree(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed, const IkOptions& options,
                              const CollisionTest& collides) const;

private:
  /// \brief A failed result when the target or the seed is unusable, else nullopt.
  std::optional<IkResult> badInput(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed) const;
  bool closedFormApplies(const IkOptions& options) const;
  /// \brief Closed-form solutions nearest `seed` first, each polished by Newton steps when the closed form
  /// lost digits (near a wrist singularity); the residual of a descent from the seed when there are none.
  std::vector<Eigen::VectorXd> closedFormCandidates(const Eigen::Isometry3d& target, const Eigen::VectorXd& seed,
                                                    const IkOptions& options, IkResult& residual) const;
  /// \brief A random start for a numeric restart: within `max_jump` of the seed on every joint when finite.
  Eigen::VectorXd restartSeed(const Eigen::VectorXd& seed, double max_jump, std::mt19937_64& rng) const;

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
