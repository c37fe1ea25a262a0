#include <algorithm>
#include <cmath>
#include <sstream>
#include <vrrw_control/arm_controller.h>
#include <vrrw_control/control_error.h>
#include <vrrw_control/stop_trajectory.h>

namespace vrrw_control
{
ArmController::ArmController(RobotHardware& hardware, const std::vector<std::string>& joints,
                             TrajectoryValidator validator, Options options)
  : hw_(hardware), joints_(joints), validator_(std::move(validator)), options_(std::move(options))
{
  if (options_.stop_deceleration.size() != joints_.size())
    throw ControlError("arm: " + std::to_string(options_.stop_deceleration.size()) +
                                " stop decelerations for " + std::to_string(joints_.size()) + " joints");
  for (const auto& j : joints_)
  {
    index_.push_back(hw_.index(j));
    if (index_.back() < 0)
      throw ControlError("arm joint " + j + ": not a joint of the robot hardware");
  }
  holdCommand();
}

void ArmController::holdCommand()
{
  hold_ = JointSample(joints_.size());
  for (size_t j = 0; j < joints_.size(); ++j)
    hold_.positions[j] = hw_.command().positions[index_[j]];
}

// motions_ is ordered by start: the latest motion that has started is the one commanded (a splice or a stop
// replaces the rest of the one before it from its own start on).
JointSample ArmController::desiredAt(double time) const
{
  for (auto m = motions_.rbegin(); m != motions_.rend(); ++m)
    if (m->start <= time)
      return m->path->sample(time - m->start);
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
  motions_.clear();
  goal_ = false;
  hold_ = JointSample(joints_.size());
  hold_.positions = positions;
  started_ = true;
}

void ArmController::holdMeasured()
{
  adopt(actual().positions);
}

void ArmController::release()
{
  motions_.clear();
  goal_ = false;
  started_ = false;
}

JointSample ArmController::restState(double now) const
{
  const auto stop = makeStopTrajectory(joints_, desiredAt(now), options_.stop_deceleration);
  JointSample rest(joints_.size());
  rest.positions = stop.points.back().positions;
  return rest;
}

ArmController::Plan ArmController::plan(const vrrw_trajectory::JointTrajectory& goal, double start_time,
                                        double now) const
{
  Plan p;
  // Splicing: the goal joins the desired motion at its start. Strict: the arm first stops with bounded
  // deceleration and the goal is validated from the rest state it stops in.
  if (options_.splice)
  {
    p.start = std::max(start_time, now);
    p.validation = validator_.splice(goal, desiredAt(p.start), p.start - start_time);
    return p;
  }
  const auto stop = makeStopTrajectory(joints_, desiredAt(now), options_.stop_deceleration);
  p.start = std::max({ start_time, now, now + stop.points.back().time });
  p.validation = validator_.validate(goal, restState(now));
  return p;
}

void ArmController::runFrom(double time, vrrw_trajectory::JointTrajectory path)
{
  motions_.erase(std::remove_if(motions_.begin(), motions_.end(), [time](const Motion& m) { return m.start >= time; }),
                 motions_.end());
  motions_.push_back({ std::make_shared<const TrajectoryInterpolator>(path), time });
}

void ArmController::start(const Plan& accepted, const Tolerances& tolerances, double now)
{
  if (!options_.splice)
    stop(now);
  runFrom(accepted.start, accepted.validation.executable);
  goal_ = true;
  goal_start_ = accepted.start;
  tolerances_ = tolerances;
}

void ArmController::stop(double now)
{
  runFrom(now, makeStopTrajectory(joints_, desiredAt(now), options_.stop_deceleration));
  goal_ = false;
}

void ArmController::endGoal(Outcome outcome, const std::string& message, double time, Cycle& cycle)
{
  cycle.outcome = outcome;
  cycle.message = message;
  cycle.goal_active = false;
  if (outcome == Outcome::Succeeded)
  {
    hold_ = motions_.back().path->sample(motions_.back().path->endTime());
    motions_.clear();
    goal_ = false;
    return;
  }
  // a measured arm holds where it is (joint_trajectory_controller's hold position): after a stall or
  // a frozen simulation the desired state may be far ahead, and the arm would jump there later
  if (hw_.measures())
    holdMeasured();
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
/// What would let a measured arm stay within `tolerance` (the parameter and goal field of that name).
std::string fixHint(const std::string& tolerance)
{
  return "; a slower time profile, a larger " + tolerance +
         " (the controller's parameter or the goal's field) or, for a held load, its weight in the drives' "
         "feed-forward (payload) would keep it within";
}
}  // namespace

// During the trajectory (t up to its end) the path tolerances apply; after it the goal tolerances, which may
// take until goal_time past the end to be met before the goal fails.
void ArmController::checkTolerances(double t, Cycle& cycle)
{
  const auto& tol = tolerances_;
  const double now = t + goal_start_;
  const double end = motions_.back().path->endTime();
  if (t <= end)
  {
    std::string why = firstViolation(joints_, cycle.error.positions, tol.path_position, "position error");
    if (why.empty())
      why = firstViolation(joints_, cycle.error.velocities, tol.path_velocity, "velocity error");
    if (!why.empty())
      endGoal(Outcome::PathToleranceViolated,
              why + " (path tolerance)" + (hw_.measures() ? fixHint("path_tolerance") : ""), now, cycle);
    return;
  }
  std::string why = firstViolation(joints_, cycle.error.positions, tol.goal_position, "position error");
  if (why.empty())
    why = firstViolation(joints_, cycle.actual.velocities, tol.goal_velocity, "velocity");
  if (why.empty())
    endGoal(Outcome::Succeeded, "", now, cycle);
  else if (t > end + tol.goal_time)
    endGoal(Outcome::GoalToleranceViolated,
            why + " (goal tolerance) " + std::to_string(tol.goal_time) + " s after the end" +
                (hw_.measures() ? fixHint("goal_tolerance") : ""),
            now, cycle);
}

ArmController::Cycle ArmController::update(double time)
{
  Cycle cycle;
  if (!started_)
    holdCommand();
  started_ = true;
  // Stages of a cycle: drop motions the next one replaced; hold the end of a finished motion (or, following a
  // measured arm, where it is); desired, actual and error; the goal's tolerances; the command written.
  while (motions_.size() > 1 && motions_[1].start <= time)
    motions_.erase(motions_.begin());
  if (!goal_ && motions_.size() == 1 && time >= motions_.front().end())
  {
    hold_ = motions_.front().path->sample(motions_.front().path->endTime());
    motions_.clear();
  }
  if (follow_measured_ && motions_.empty() && hw_.measures())
  {
    hold_ = JointSample(joints_.size());
    hold_.positions = actual().positions;
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
  if (goal_)
  {
    cycle.goal_active = true;
    if (time >= goal_start_)
      checkTolerances(time - goal_start_, cycle);
    if (cycle.outcome == Outcome::PathToleranceViolated || cycle.outcome == Outcome::GoalToleranceViolated)
      cycle.desired = desiredAt(time);  // already this cycle's command holds
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
