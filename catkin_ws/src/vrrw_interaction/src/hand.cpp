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
