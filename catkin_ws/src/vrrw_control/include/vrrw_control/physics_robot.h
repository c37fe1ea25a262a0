#pragma once
#include <vrrw_control/drive_link.h>
#include <vrrw_control/robot_hardware.h>

namespace vrrw_control
{
/// \brief A robot simulated by the physics node: write() streams drive targets, read() takes its joint_states.
class PhysicsRobot : public RobotHardware
{
public:
  PhysicsRobot(std::vector<std::string> joints, DriveLink& link);
  void read(double time, double period) override;
  void write(double time, double period) override;
  bool ready() const override { return ready_; }

private:
  DriveLink& link_;
  bool ready_ = false;
};
}  // namespace vrrw_control
