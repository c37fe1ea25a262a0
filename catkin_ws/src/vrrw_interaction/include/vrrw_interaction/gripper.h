#pragma once
#include <optional>
#include <string>
#include <vrrw_kinematics/robot_model.h>
#include <vrrw_scene/scene.h>

namespace vrrw_interaction
{
/// \brief Where a gripper's actuated joint stands open and closed. The direction differs by kind: a Robotiq
/// knuckle (revolute) closes as its angle grows, lower limit open; Fetch's prismatic fingers set the gap, so
/// they close as it shrinks, upper limit open.
struct GripperRange
{
  std::string joint;  ///< the actuated joint (prefixed)
  double open = 0.0;
  double closed = 0.0;

  /// \brief 0 at open, 1 at closed, linear in between (beyond the limits: beyond 0 and 1).
  double closedFraction(double position) const;
};

/// \brief The range of `robot`'s first actuated gripper joint in `model`; none for a robot without a gripper.
std::optional<GripperRange> gripperRange(const vrrw_kinematics::RobotModel& model, const vrrw_scene::Robot& robot);
}  // namespace vrrw_interaction
