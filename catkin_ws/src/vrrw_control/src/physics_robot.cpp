#include <sstream>
#include <vrrw_control/physics_robot.h>

namespace vrrw_control
{
PhysicsRobot::PhysicsRobot(std::vector<std::string> joints, DriveLink& link, double state_timeout)
  : RobotHardware(std::move(joints)), link_(link), state_timeout_(state_timeout)
{
}

void PhysicsRobot::read(double, double)
{
  const bool was_ready = ready_;
  measured_ = link_.latestState(joints_, state_, efforts_);
  ready_ = measured_ && link_.stateAge() <= state_timeout_;
  if (ready_ && !was_ready)
  {
    // first state, or the first after the states stopped: hold what is measured now
    command_ = state_;
    command_.velocities.assign(joints_.size(), 0.0);
    command_.accelerations.assign(joints_.size(), 0.0);
  }
}

void PhysicsRobot::write(double time, double)
{
  if (ready_)
    link_.sendTargets(joints_, command_, effort_limits_, time);
}

std::string PhysicsRobot::fault() const
{
  if (ready_)
    return "";
  if (!measured_)
    return "no joint_states received for this robot yet";
  std::ostringstream why;
  why.precision(3);
  why << "no joint_states for " << link_.stateAge() << " s (state_timeout " << state_timeout_
      << " s): is the physics node running?";
  return why.str();
}
}  // namespace vrrw_control
