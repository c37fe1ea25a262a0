#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <string>

#include "vrrw_kinematics/kinematics_error.h"

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
};

/// \brief The answer to an IK request.
struct IkResult
{
  bool success = false;
  ErrorCode code = ErrorCode::NoSolution;
  std::string message;
  Eigen::VectorXd q;
  double position_error = 0.0;
  double orientation_error = 0.0;
  int attempts = 0;
};
}  // namespace vrrw_kinematics
