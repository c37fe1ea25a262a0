#pragma once
#include <vrrw_control/robot_hardware.h>

namespace vrrw_control
{
/// \brief The controller is the robot: the state equals the command (the paper's fake joint controller).
class FakeRobot : public RobotHardware
{
public:
  using RobotHardware::RobotHardware;
  void read(double time, double period) override;
  void write(double time, double period) override;
  bool measures() const override { return false; }
};
}  // namespace vrrw_control
