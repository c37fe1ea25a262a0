#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <limits>
#include <string>

#include <vrrw_kinematics/contact.h>
#include <vrrw_kinematics/kinematics_error.h>

namespace vrrw_kinematics
{
/// \brief What an IK request asks for.
struct IkOptions
{
  enum class Mode { Full, PositionOnly, OrientationTolerant };
  Mode mode = Mode::Full;
  double tolerance = 1e-5;              ///< position (m) and orientation (rad) error accepted
  double orientation_tolerance = 0.0;   ///< rad, OrientationTolerant: rotation error allowed about any axis
  double timeout = 0.005;               ///< s, random restarts until then
  std::uint64_t seed = 1;               ///< seeds the restarts
  bool allow_analytic = true;           ///< use the closed form when the chain has one
  bool nearest = false;                 ///< numeric: keep restarting until the timeout, return the solution
                                        ///< nearest the seed (else the first one, found from the seed itself)
  /// Largest |q_i - seed_i| (rad, m) a solution may have: a solution farther from the seed is a branch
  /// flip (elbow or wrist turning over) and is refused with ErrorCode::JointJump (solveCollisionFree).
  double max_jump = std::numeric_limits<double>::infinity();
};

/// \brief The answer to an IK request.
struct IkResult
{
  bool success = false;
  ErrorCode code = ErrorCode::NoSolution;
  std::string message;
  Eigen::VectorXd q;
  double position_error = 0.0;     ///< m; on NoSolution: the smallest residual reached
  double orientation_error = 0.0;  ///< rad; on NoSolution: at that residual
  double jump = 0.0;               ///< max_i |q_i - seed_i| of q, or on JointJump of the nearest solution
  Contact contact;                 ///< on InCollision: the pair the nearest solution within max_jump touches
  int attempts = 0;
};
}  // namespace vrrw_kinematics
