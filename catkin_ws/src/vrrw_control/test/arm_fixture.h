#pragma once
// Limits, goals and robots shared by the ArmController tests.
#include <vrrw_control/arm_controller.h>
#include <vrrw_control/fake_robot.h>

namespace vrrw_control_test
{
using namespace vrrw_control;

inline std::vector<JointLimits> limits(const std::vector<std::string>& names)
{
  std::vector<JointLimits> l(names.size());
  for (size_t j = 0; j < names.size(); ++j)
  {
    l[j].name = names[j];
    l[j].max_velocity = 2.0;
    l[j].max_acceleration = 4.0;
  }
  return l;
}

inline ArmController::Options options(size_t joints, bool splice = true)
{
  ArmController::Options o;
  o.splice = splice;
  o.stop_deceleration.assign(joints, 4.0);
  return o;
}

/// Every joint from 0 to `to` in `duration`, at rest at both ends (cubic).
inline vrrw_trajectory::JointTrajectory ramp(const std::vector<std::string>& names, double to, double duration,
                                             double from = 0.0)
{
  vrrw_trajectory::JointTrajectory g;
  g.joint_names = names;
  vrrw_trajectory::TrajectoryPoint a, b;
  a.positions.assign(names.size(), from);
  a.velocities.assign(names.size(), 0.0);
  b = a;
  b.positions.assign(names.size(), to);
  b.time = duration;
  g.points = { a, b };
  return g;
}

inline Tolerances noTolerances(size_t joints)
{
  return Tolerances::uniform(joints, 0.0, 0.0, 0.0, 0.0);
}

/// Follows the command one cycle late and lags by a fixed offset on the first joint.
class LaggingRobot : public RobotHardware
{
public:
  LaggingRobot(std::vector<std::string> j, double offset) : RobotHardware(std::move(j)), offset_(offset) {}
  void read(double, double) override {}
  void write(double, double) override
  {
    state_ = command_;
    state_.positions[0] -= offset_;
  }

private:
  double offset_;
};

/// A measured robot that follows its command exactly, except while frozen (a physics step guard
/// rejecting steps) or pushed (an operator moving a compliant arm): then the state is set from outside.
class MeasuredRobot : public RobotHardware
{
public:
  using RobotHardware::RobotHardware;
  void read(double, double) override {}
  void write(double, double) override
  {
    if (!frozen)
      state_ = command_;
  }
  void push(const std::vector<double>& positions)
  {
    state_.positions = positions;
    state_.velocities.assign(positions.size(), 0.0);
  }
  bool frozen = false;
};
}  // namespace vrrw_control_test
