#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vrrw_control/arm_controller.h>
#include <vrrw_control/stop_trajectory.h>

namespace vrrw_control
{
ArmController::ArmController(RobotHardware& hardware, const std::vector<std::string>& joints,
                             TrajectoryValidator validator, std::vector<double> stop_deceleration)
  : hw_(hardware), joints_(joints), validator_(std::move(validator)), stop_deceleration_(std::move(stop_deceleration))
{
  for (const auto& j : joints_)
  {
    index_.push_back(hw_.index(j));
    if (index_.back() < 0)
      throw std::invalid_argument("arm joint " + j + ": not a joint of the robot hardware");
  }
  holdCommand();
}

void ArmController::holdCommand()
{
  hold_ = JointSample(joints_.size());
  for (size_t j = 0; j < joints_.size(); ++j)
    hold_.positions[j] = hw_.command().positions[index_[j]];
}

JointSample ArmController::desiredAt(double time) const
{
  if (motion_ && (time >= motion_start_ || !stopping_))
    return motion_->sample(time - motion_start_);
  if (stopping_)
    return stopping_->sample(time);
  return hold_;
}

JointSample ArmController::actual() const
{
  JointSample a(joints_.size());
  for (size_t j = 0; j < joints_.size(); ++j)
  {
    a.positions[j] = hw_.state().positions[index_[j]];
    a.velocities[j] = hw_.state().velocities[index_[j]];
    a.accelerations[j] = hw_.state().accelerations[index_[j]];
  }
  return a;
}

void ArmController::adopt(const std::vector<double>& positions)
{
  motion_.reset();
  stopping_.reset();
  hold_ = JointSample(joints_.size());
  hold_.positions = positions;
  started_ = true;
}

bool ArmController::moving() const { return motion_ || stopping_; }

JointSample ArmController::restState(double now) const
{
  const JointSample d = desiredAt(now);
  const auto stop = makeStopTrajectory(joints_, d, stop_deceleration_);
  JointSample rest(joints_.size());
  rest.positions = stop.points.back().positions;
  return rest;
}

Validation ArmController::validate(const vrrw_trajectory::JointTrajectory& goal, double now) const
{
  return validator_.validate(goal, restState(now));
}

void ArmController::stop(double now)
{
  const JointSample d = desiredAt(now);
  auto stop = makeStopTrajectory(joints_, d, stop_deceleration_);
  for (auto& p : stop.points)
    p.time += now;
  stopping_ = std::make_unique<TrajectoryInterpolator>(stop);
  motion_.reset();
}

void ArmController::start(const Validation& accepted, double start_time, double now, const Tolerances& tolerances)
{
  stop(now);
  motion_ = std::make_unique<TrajectoryInterpolator>(accepted.executable);
  motion_start_ = std::max(start_time, stopping_->endTime());
  tolerances_ = tolerances;
}

void ArmController::endGoal(Outcome outcome, const std::string& message, double time, Cycle& cycle)
{
  cycle.outcome = outcome;
  cycle.message = message;
  cycle.goal_active = false;
  if (outcome == Outcome::Succeeded)
  {
    hold_ = motion_->sample(motion_->endTime());
    motion_.reset();
    stopping_.reset();
  }
  else
    stop(time);
}

namespace
{
/// One line naming the first joint whose |value| exceeds its (checked, > 0) tolerance, or "".
std::string firstViolation(const std::vector<std::string>& joints, const std::vector<double>& values,
                           const std::vector<double>& tolerances, const std::string& what)
{
  for (size_t j = 0; j < joints.size(); ++j)
    if (tolerances[j] > 0.0 && std::abs(values[j]) > tolerances[j])
    {
      std::ostringstream why;
      why << "joint " << joints[j] << ": " << what << " " << std::abs(values[j]) << " exceeds " << tolerances[j];
      return why.str();
    }
  return "";
}
}  // namespace

void ArmController::checkTolerances(double t, Cycle& cycle)
{
  const auto& tol = tolerances_;
  const double now = t + motion_start_;
  if (t <= motion_->endTime())
  {
    std::string why = firstViolation(joints_, cycle.error.positions, tol.path_position, "position error");
    if (why.empty())
      why = firstViolation(joints_, cycle.error.velocities, tol.path_velocity, "velocity error");
    if (!why.empty())
      endGoal(Outcome::PathToleranceViolated, why + " (path tolerance)", now, cycle);
    return;
  }
  std::string why = firstViolation(joints_, cycle.error.positions, tol.goal_position, "position error");
  if (why.empty())
    why = firstViolation(joints_, cycle.actual.velocities, tol.goal_velocity, "velocity");
  if (why.empty())
    endGoal(Outcome::Succeeded, "", now, cycle);
  else if (t > motion_->endTime() + tol.goal_time)
    endGoal(Outcome::GoalToleranceViolated,
            why + " (goal tolerance) " + std::to_string(tol.goal_time) + " s after the end", now, cycle);
}

ArmController::Cycle ArmController::update(double time)
{
  Cycle cycle;
  if (!started_)
    holdCommand();
  started_ = true;
  if (stopping_ && !motion_ && time >= stopping_->endTime())
  {
    hold_ = stopping_->sample(stopping_->endTime());
    stopping_.reset();
  }
  cycle.desired = desiredAt(time);
  cycle.actual = actual();
  cycle.error = JointSample(joints_.size());
  for (size_t j = 0; j < joints_.size(); ++j)
  {
    cycle.error.positions[j] = cycle.desired.positions[j] - cycle.actual.positions[j];
    cycle.error.velocities[j] = cycle.desired.velocities[j] - cycle.actual.velocities[j];
    cycle.error.accelerations[j] = cycle.desired.accelerations[j] - cycle.actual.accelerations[j];
  }
  if (motion_)
  {
    cycle.goal_active = true;
    if (time >= motion_start_)
    {
      stopping_.reset();
      checkTolerances(time - motion_start_, cycle);
    }
  }
  auto& cmd = hw_.command();
  for (size_t j = 0; j < joints_.size(); ++j)
  {
    cmd.positions[index_[j]] = cycle.desired.positions[j];
    cmd.velocities[index_[j]] = cycle.desired.velocities[j];
    cmd.accelerations[index_[j]] = cycle.desired.accelerations[j];
  }
  return cycle;
}
}  // namespace vrrw_control
