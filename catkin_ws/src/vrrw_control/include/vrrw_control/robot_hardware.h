#pragma once
#include <string>
#include <vector>
#include <vrrw_control/joint_sample.h>

namespace vrrw_control
{
/// \brief What stands between controllers and a robot, after ros_control's RobotHW: read() fills
/// the measured state, controllers write the command, write() sends it.
class RobotHardware
{
public:
  explicit RobotHardware(std::vector<std::string> joints);
  virtual ~RobotHardware() = default;

  /// \brief Fetches the measured state for the control cycle at `time` (seconds).
  virtual void read(double time, double period) = 0;
  /// \brief Sends the command of this cycle.
  virtual void write(double time, double period) = 0;
  /// \brief True while a fresh measured state exists for every joint.
  virtual bool ready() const { return true; }
  /// \brief Why the hardware is not ready, one line; empty when it is.
  virtual std::string fault() const { return ""; }
  /// \brief False when the state is the command itself (a fake robot), true when it is measured.
  virtual bool measures() const { return true; }

  const std::vector<std::string>& joints() const { return joints_; }
  /// \brief Index of a joint, or -1.
  int index(const std::string& joint) const;

  const JointSample& state() const { return state_; }
  const std::vector<double>& efforts() const { return efforts_; }
  JointSample& command() { return command_; }
  const JointSample& command() const { return command_; }
  /// \brief Drive force/torque limit per joint while the command holds (N, N m); 0: the configured one.
  std::vector<double>& effortLimits() { return effort_limits_; }
  const std::vector<double>& effortLimits() const { return effort_limits_; }

  /// \brief Sets state and command to one resting configuration (start-up).
  void reset(const std::vector<double>& positions);

protected:
  std::vector<std::string> joints_;
  JointSample state_;
  JointSample command_;
  std::vector<double> efforts_;
  std::vector<double> effort_limits_;
};
}  // namespace vrrw_control
