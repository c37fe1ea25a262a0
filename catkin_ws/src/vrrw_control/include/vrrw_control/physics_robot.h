#pragma once
#include <vrrw_control/robot_hardware.h>

namespace vrrw_control
{
/// \brief A robot simulated in the same process, by physics_node's stepping thread: before each control cycle
/// the simulation hands in the state it measured at the start of its step (measure()), read() takes it, and
/// after the cycle the simulation takes command() and effortLimits() as the step's drive targets. Ready once
/// measured.
class PhysicsRobot : public RobotHardware
{
public:
  using RobotHardware::RobotHardware;
  /// \brief The state measured at the start of this step (the order of joints()).
  void measure(const std::vector<double>& positions, const std::vector<double>& velocities,
               const std::vector<double>& efforts);
  void read(double time, double period) override;
  void write(double, double) override {}
  bool ready() const override { return measured_; }
  std::string fault() const override { return measured_ ? "" : "no state measured by physics yet"; }
  /// \brief The next read() holds what it measures (at rest): after the simulation jumped or stopped.
  void holdMeasured() { hold_ = true; }

private:
  JointSample measurement_;
  std::vector<double> measured_efforts_;
  bool measured_ = false;  ///< some state arrived
  bool hold_ = true;       ///< the next read commands what it measures
};
}  // namespace vrrw_control
