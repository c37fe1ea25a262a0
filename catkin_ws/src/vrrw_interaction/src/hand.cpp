#include <vrrw_interaction/hand.h>

#include <cmath>
#include <sstream>

namespace vrrw_interaction
{
void Hand::setPose(const Eigen::Isometry3d& pose, double t)
{
  pose_ = pose;
  stamp_ = t;
  has_pose_ = true;
}

Hand::GripChange Hand::setGrip(double grip)
{
  const bool closed = grip >= 0.5;
  if (closed == closed_)
    return GripChange::None;
  closed_ = closed;
  return closed ? GripChange::Close : GripChange::Open;
}

void Hand::hold(const GrabTarget& target)
{
  held_ = target;
  point_in_hand_ = pose_.inverse() * target.point_in_world;
  pose_at_grab_ = pose_;
}

Eigen::Isometry3d tcpPose(vrrw_kinematics::Arm& arm, const Eigen::VectorXd& world_state)
{
  return arm.basePose(world_state) * arm.ikSolver().chain().fk(arm.jointValues(world_state));
}

vrrw_kinematics::IkResult armFollowingHand(vrrw_kinematics::Arm& arm, const Hand& hand,
                                           const Eigen::Isometry3d& tcp_at_grab, const Eigen::VectorXd& world_state,
                                           double max_jump)
{
  vrrw_kinematics::IkOptions options;
  options.max_jump = max_jump;
  return arm.solveCollisionFree(hand.carried(tcp_at_grab), arm.jointValues(world_state), world_state, options);
}

std::string gripError(double grip)
{
  if (!std::isfinite(grip))
    return "not finite";
  if (grip < 0.0 || grip > 1.0)
  {
    std::ostringstream out;
    out << grip << " outside [0, 1] (0 open, 1 closed)";
    return out.str();
  }
  return "";
}
}  // namespace vrrw_interaction
