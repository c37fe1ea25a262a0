#pragma once
#include <memory>
#include <string>
#include <vrrw_control/robot_hardware.h>
#include <vrrw_control/trajectory_interpolator.h>

namespace vrrw_control
{
/// \brief Options of a gripper; positions are those of its actuated joint.
struct GripperOptions
{
  double min_position = 0.0, max_position = 0.8;
  double max_velocity = 1.0;       ///< rad/s (m/s) of the actuated joint
  double min_duration = 0.5;       ///< s for any move
  double goal_tolerance = 0.01;
  double stall_velocity = 0.01;    ///< mean speed over stall_time below which the fingers do not move
  double stall_time = 0.2;         ///< s without motion short of the goal: stalled
  double timeout = 5.0;            ///< s after the planned move end
  /// \brief m: a pad force F (GripperCommand max_effort, N) is the actuated joint's drive force limit
  /// F x lever_arm (the gripper config's fingertip_lever_arm). 0: max_effort is not enforced.
  double lever_arm = 0.0;
  double max_grip_force = 0.0;  ///< N, the rated pad force: what max_effort 0 squeezes with; larger
                                ///< max_effort is refused (0: no bound, max_effort 0 the drive's own limit)
};

/// \brief Moves the actuated gripper joint along a smooth cubic to the commanded position and
/// reports reached_goal, or stalled when the fingers stop short (closed on an object).
class GripperController
{
public:
  struct Cycle
  {
    bool goal_active = false;
    bool done = false;  ///< set once, in the cycle the goal ends
    bool reached_goal = false, stalled = false, timed_out = false;
    double position = 0.0, effort = 0.0;
  };

  GripperController(RobotHardware& hardware, const std::string& joint, GripperOptions options);

  /// \brief Empty when acceptable, else one line naming the field and the reason. `max_effort`: the
  /// pad force in N, as Robotiq rates grip force (0: the rated max_grip_force; without one, the configured
  /// drive limit).
  std::string check(double position, double max_effort = 0.0) const;
  /// \brief Moves to `position`, squeezing with at most `max_effort` N per pad (0: the rated max_grip_force;
  /// without one, the configured drive limit) until the next goal.
  void start(double position, double now, double max_effort = 0.0);
  void stop(double now);
  /// \brief Ends the goal and forgets the state: the next update() holds what the hardware commands then.
  void release();
  /// \brief One control cycle; the first holds whatever the hardware commands then.
  Cycle update(double time);

  const std::string& joint() const { return joint_; }

private:
  RobotHardware& hw_;
  std::string joint_;
  int index_;
  GripperOptions options_;
  std::unique_ptr<TrajectoryInterpolator> motion_;
  double start_time_ = 0.0, target_ = 0.0, hold_ = 0.0;
  double effort_limit_ = 0.0;  ///< N m on the actuated joint, 0: configured
  double window_position_ = 0.0, window_start_ = 0.0;  ///< where and when the fingers last moved
  bool active_ = false;
  bool started_ = false;
};
}  // namespace vrrw_control
