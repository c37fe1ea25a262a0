#include <algorithm>
#include <cmath>
#include <sstream>
#include <vrrw_control/control_error.h>
#include <vrrw_control/gripper_controller.h>

namespace vrrw_control
{
GripperController::GripperController(RobotHardware& hardware, const std::string& joint, GripperOptions options)
  : hw_(hardware), joint_(joint), index_(hardware.index(joint)), options_(options)
{
  if (index_ < 0)
    throw ControlError("gripper joint " + joint + ": not a joint of the robot hardware");
  hold_ = hw_.command().positions[index_];
}

std::string GripperController::check(double position, double max_effort) const
{
  std::ostringstream why;
  if (!std::isfinite(position))
    why << "joint " << joint_ << ": position is not finite";
  else if (position < options_.min_position || position > options_.max_position)
    why << "joint " << joint_ << ": position " << position << " outside limits [" << options_.min_position << ", "
        << options_.max_position << "]";
  else if (!std::isfinite(max_effort) || max_effort < 0.0)
    why << "max_effort " << max_effort << ": must be a finite grip force >= 0 N (0: the default)";
  else if (options_.max_grip_force > 0.0 && max_effort > options_.max_grip_force)
    why << "max_effort " << max_effort << " N exceeds the gripper's rated grip force " << options_.max_grip_force
        << " N";
  return why.str();
}

void GripperController::start(double position, double now, double max_effort)
{
  // 0 asks for the gripper's rated force, not for the drive's own limit: the simulated 2F-85's finger drive
  // squeezes 625 N per pad at its limit, 2.7 times what the real one is rated for, and a squeeze that hard
  // pushes a held object out of the fingers or the arm off its goal (issue 22).
  const double force = max_effort > 0.0 ? max_effort : options_.max_grip_force;
  effort_limit_ = force > 0.0 && options_.lever_arm > 0.0 ? force * options_.lever_arm : 0.0;
  const double from = motion_ ? motion_->sample(now - start_time_).positions[0] : hold_;
  vrrw_trajectory::JointTrajectory move;
  move.joint_names = { joint_ };
  vrrw_trajectory::TrajectoryPoint a, b;
  a.positions = { from };
  a.velocities = { 0.0 };
  b.positions = { position };
  b.velocities = { 0.0 };
  // a cubic from rest to rest peaks at 1.5 times its mean velocity: this duration keeps that peak at the limit
  b.time = std::max(options_.min_duration, 1.5 * std::abs(position - from) / options_.max_velocity);
  move.points = { a, b };
  motion_ = std::make_unique<TrajectoryInterpolator>(move);
  start_time_ = now;
  target_ = position;
  window_position_ = hw_.state().positions[index_];
  window_start_ = now;
  active_ = true;
}

void GripperController::stop(double now)
{
  if (motion_)
    hold_ = motion_->sample(now - start_time_).positions[0];
  motion_.reset();
  active_ = false;
}

void GripperController::release()
{
  motion_.reset();
  active_ = false;
  started_ = false;
}

GripperController::Cycle GripperController::update(double time)
{
  Cycle c;
  if (!started_)
    hold_ = hw_.command().positions[index_];
  started_ = true;
  const double commanded = motion_ ? motion_->sample(time - start_time_).positions[0] : hold_;
  hw_.command().positions[index_] = commanded;
  hw_.command().velocities[index_] = motion_ ? motion_->sample(time - start_time_).velocities[0] : 0.0;
  hw_.effortLimits()[index_] = effort_limit_;
  c.position = hw_.state().positions[index_];
  c.effort = hw_.efforts()[index_];
  if (!active_)
    return c;
  c.goal_active = true;
  const double end = start_time_ + motion_->endTime();
  c.reached_goal = time >= end && std::abs(c.position - target_) <= options_.goal_tolerance;
  // A stall: the fingers moved less than stall_velocity * stall_time over the last stall_time, short of the
  // target (an object between them). The window restarts whenever they move more.
  if (std::abs(c.position - window_position_) > options_.stall_velocity * options_.stall_time)
  {
    window_position_ = c.position;
    window_start_ = time;
  }
  c.stalled = !c.reached_goal && time - window_start_ >= options_.stall_time &&
              std::abs(c.position - target_) > options_.goal_tolerance;
  c.timed_out = !c.reached_goal && !c.stalled && time > end + options_.timeout;
  if (c.reached_goal || c.stalled || c.timed_out)
  {
    c.done = true;
    c.goal_active = false;
    active_ = false;
    hold_ = target_;  // a stalled gripper keeps commanding the target: it squeezes at its effort limit
    motion_.reset();
  }
  return c;
}
}  // namespace vrrw_control
