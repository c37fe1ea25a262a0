#include <vrrw_kinematics/kinematics_error.h>

namespace vrrw_kinematics
{
const char* errorCodeName(ErrorCode code)
{
  switch (code)
  {
    case ErrorCode::Ok: return "ok";
    case ErrorCode::InvalidUrdf: return "invalid_urdf";
    case ErrorCode::UnknownLink: return "unknown_link";
    case ErrorCode::NotSerialChain: return "not_serial_chain";
    case ErrorCode::InvalidPose: return "invalid_pose";
    case ErrorCode::NoSolution: return "no_solution";
    case ErrorCode::OutsideLimits: return "outside_limits";
    case ErrorCode::InCollision: return "in_collision";
    case ErrorCode::PlanningFailed: return "planning_failed";
    case ErrorCode::InvalidArgument: return "invalid_argument";
    case ErrorCode::JointJump: return "joint_jump";
  }
  return "unknown";
}
}  // namespace vrrw_kinematics
