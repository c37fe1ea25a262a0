#include <vrrw_control/physics_robot.h>

namespace vrrw_control
{
PhysicsRobot::PhysicsRobot(std::vector<std::string> joints, DriveLink& link)
  : RobotHardware(std::move(joints)), link_(link)
{
}

void PhysicsRobot::read(double, double)
{
  const bool was_ready = ready_;
  ready_ = link_.latestState(joints_, state_, efforts_);
  if (ready_ && !was_ready)
  {
    command_ = state_;
    command_.velocities.assign(joints_.size(), 0.0);
    command_.accelerations.assign(joints_.size(), 0.0);
  }
}

void PhysicsRobot::write(double time, double)
{
  if (ready_)
    link_.sendTargets(joints_, command_, time);
}
}  // namespace vrrw_control
