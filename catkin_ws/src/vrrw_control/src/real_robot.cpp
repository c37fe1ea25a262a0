#include <vrrw_control/real_robot.h>

namespace vrrw_control
{
RealRobot::RealRobot(std::vector<std::string> joints, DriveLink& link)
  : RobotHardware(std::move(joints)), link_(link)
{
}

void RealRobot::read(double, double)
{
  ready_ = link_.latestState(joints_, state_, efforts_);
  if (ready_)
    command_ = state_;
}
}  // namespace vrrw_control
