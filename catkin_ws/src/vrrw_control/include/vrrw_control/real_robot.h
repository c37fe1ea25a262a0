#pragma once
#include <vrrw_control/drive_link.h>
#include <vrrw_control/robot_hardware.h>

namespace vrrw_control
{
/// \brief A real arm behind its own driver: read() takes the driver's measured joint states; write()
/// sends nothing, because the real arm executes whole goals handed over by RealDriverRelay.
class RealRobot : public RobotHardware
{
public:
  RealRobot(std::vector<std::string> joints, DriveLink& link);
  void read(double time, double period) override;
  void write(double, double) override {}
  bool ready() const override { return ready_; }

private:
  DriveLink& link_;
  bool ready_ = false;
};
}  // namespace vrrw_control
