#include <vrrw_control/fake_robot.h>

namespace vrrw_control
{
void FakeRobot::read(double, double) {}

void FakeRobot::write(double, double) { state_ = command_; }
}  // namespace vrrw_control
