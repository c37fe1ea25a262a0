#include <vrrw_control/physics_robot.h>

namespace vrrw_control
{
void PhysicsRobot::measure(const std::vector<double>& positions, const std::vector<double>& velocities,
                           const std::vector<double>& efforts)
{
  measurement_.positions = positions;
  measurement_.velocities = velocities;
  measurement_.accelerations.assign(positions.size(), 0.0);
  measured_efforts_ = efforts;
  measured_ = true;
}

void PhysicsRobot::read(double, double)
{
  if (!measured_)
    return;
  state_ = measurement_;
  efforts_ = measured_efforts_;
  if (hold_)
  {
    // the first state, or the first after a jump: hold what is measured now
    command_ = state_;
    command_.velocities.assign(joints_.size(), 0.0);
    hold_ = false;
  }
}
}  // namespace vrrw_control
