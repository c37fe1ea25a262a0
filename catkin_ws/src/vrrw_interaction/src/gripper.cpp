#include <vrrw_interaction/gripper.h>

#include <algorithm>

namespace vrrw_interaction
{
double GripperRange::closedFraction(double position) const
{
  const double span = closed - open;
  return std::abs(span) < 1e-12 ? 0.0 : (position - open) / span;
}

std::optional<GripperRange> gripperRange(const vrrw_kinematics::RobotModel& model, const vrrw_scene::Robot& robot)
{
  if (robot.gripper_joints.empty())
    return std::nullopt;
  const vrrw_kinematics::JointModel& joint = model.joints()[model.jointIndex(robot.gripper_joints.front())];
  const bool gap = joint.type == vrrw_kinematics::JointModel::Type::Prismatic;
  return GripperRange{ joint.name, gap ? joint.upper : joint.lower, gap ? joint.lower : joint.upper };
}
}  // namespace vrrw_interaction
