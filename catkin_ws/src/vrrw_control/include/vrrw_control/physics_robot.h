#pragma once
#include <vrrw_control/drive_link.h>
#include <vrrw_control/robot_hardware.h>

namespace vrrw_control
{
/// \brief A robot simulated by the physics node: write() streams drive targets, read() takes its
/// joint_states. Ready while a state newer than `state_timeout` s (wall clock) exists: when the
/// physics node dies its states and its /clock stop, and the controller must notice without either.
class PhysicsRobot : public RobotHardware
{
public:
  PhysicsRobot(std::vector<std::string> joints, DriveLink& link, double state_timeout = 1.0);
  void read(double time, double period) override;
  void write(double time, double period) override;
  bool ready() const override { return ready_; }
  std::string fault() const override;

private:
  DriveLink& link_;
  double state_timeout_;
  bool measured_ = false;  ///< some complete state arrived once
  bool ready_ = false;
};
}  // namespace vrrw_control
