#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_kinematics
{
/// \brief Why a kinematics, collision or planning request failed.
enum class ErrorCode
{
  Ok = 0,
  InvalidUrdf = 1,
  UnknownLink = 2,
  NotSerialChain = 3,
  InvalidPose = 4,
  NoSolution = 5,
  OutsideLimits = 6,
  InCollision = 7,
  PlanningFailed = 8,
  InvalidArgument = 9,
  JointJump = 10,  ///< an IK solution exists, but only farther from the seed than allowed (a branch flip)
};

/// \brief Short stable name of an error code ("unknown_link", ...).
const char* errorCodeName(ErrorCode code);

/// \brief A bad request; what() is one line naming the thing (link, joint, field) and the reason.
class KinematicsError : public std::runtime_error
{
public:
  KinematicsError(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const { return code_; }

private:
  ErrorCode code_;
};
}  // namespace vrrw_kinematics
