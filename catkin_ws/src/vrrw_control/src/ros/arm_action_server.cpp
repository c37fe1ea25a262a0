#include <vrrw_control/ros/arm_action_server.h>
#include <vrrw_control/ros/msg_conversions.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_control
{
namespace
{
using Result = control_msgs::FollowJointTrajectoryResult;

int codeOf(Validation::Error e)
{
  return e == Validation::Error::InvalidJoints ? Result::INVALID_JOINTS : Result::INVALID_GOAL;
}

const char* const kFreeDrive = "free-drive active";
}  // namespace

// actionlib reads these parameters when the server or client is made.
ros::NodeHandle actionParameters(ros::NodeHandle& nh, const std::string& name,
                                 const ArmActionServer::Options& options)
{
  for (const char* side : { "server", "client" })
  {
    nh.setParam(name + "/actionlib_" + side + "_sub_queue_size", options.queue_size);
    nh.setParam(name + "/actionlib_" + side + "_pub_queue_size", options.queue_size);
  }
  nh.setParam(name + "/actionlib_status_frequency", 0.0);
  return nh;
}

ArmActionServer::ArmActionServer(ros::NodeHandle& nh, ArmController& arm, const RobotHardware& hardware,
                                 Options options, std::unique_ptr<RealDriverRelay> relay, const RobotHardware* real)
  : arm_(arm)
  , hw_(hardware)
  , options_(std::move(options))
  , origin_(options_.clock_origin)
  , relay_(std::move(relay))
  , real_(real)
  , server_(actionParameters(nh, "arm_controller/follow_joint_trajectory", options_),
            "arm_controller/follow_joint_trajectory", options_.status_period, [this](GoalHandle gh) { onGoal(gh); },
            [this](GoalHandle gh) { onCancel(gh); })
  , name_(nh.getNamespace() + "/arm_controller")
{
  if (relay_)
    confirm_ = nh.advertiseService("arm_controller/confirm_real_execution", &ArmActionServer::onConfirm, this);
  server_.start();
}

void ArmActionServer::reject(GoalHandle& gh, int code, const std::string& message)
{
  Result r;
  r.error_code = code;
  r.error_string = message;
  gh.setRejected(r, message);
  ROS_WARN_STREAM(name_ << ": goal rejected: " << message);
}

void ArmActionServer::finish(int code, const std::string& message)
{
  Result r;
  r.error_code = code;
  r.error_string = message;
  if (code == Result::SUCCESSFUL)
    active_.setSucceeded(r, message);
  else
  {
    active_.setAborted(r, message);
    ROS_WARN_STREAM(name_ << ": goal aborted: " << message);
  }
  phase_ = Phase::Idle;
}

std::pair<int, std::string> ArmActionServer::admissible(const control_msgs::FollowJointTrajectoryGoal& goal,
                                                        const ros::Time& start, const ros::Time& now) const
{
  if (free_drive_)
    return { Result::INVALID_GOAL, kFreeDrive };
  if (!hw_.ready())
    return { Result::INVALID_GOAL, hw_.fault() };
  if (!goal.trajectory.points.empty() && start + goal.trajectory.points.back().time_from_start < now)
    return { Result::OLD_HEADER_TIMESTAMP,
             "trajectory ended " + std::to_string((now - start - goal.trajectory.points.back().time_from_start).toSec()) +
                 " s ago (header.stamp in the past)" };
  if (phase_ == Phase::Relaying)
    return { Result::INVALID_GOAL, "a goal is executing on the real robot; cancel it first" };
  return { Result::SUCCESSFUL, "" };
}

// A goal's way in: (1) admitted (free-drive, hardware, stamp, a real goal running), (2) its tolerances
// applied, (3) validated from where the arm will be (real mode with a measured arm: from the real arm's state,
// strictly; otherwise planned into the running motion), (4) the running goal preempted, (5) started.
void ArmActionServer::onGoal(GoalHandle gh)
{
  const auto goal = gh.getGoal();
  const ros::Time now = options_.clock();
  const ros::Time start = goal->trajectory.header.stamp.isZero() ? now : goal->trajectory.header.stamp;
  const auto [code, why] = admissible(*goal, start, now);
  if (!why.empty())
    return reject(gh, code, why);
  Tolerances tolerances = options_.defaults;
  const std::string bad = applyTolerances(goal->path_tolerance, goal->goal_tolerance,
                                          goal->goal_time_tolerance.toSec(), arm_.joints(), tolerances);
  if (!bad.empty())
    return reject(gh, Result::INVALID_GOAL, bad);

  const auto trajectory = vrrw_trajectory::fromMsg(goal->trajectory);
  const bool measured = real_ && real_->ready();
  ArmController::Plan plan;
  if (measured)
  {
    JointSample real_state(arm_.joints().size());
    real_state.positions = realArm();
    plan.validation = arm_.validator().validate(trajectory, real_state);
    plan.start = toTime(std::max(start, now));
  }
  else
    plan = arm_.plan(trajectory, toTime(start), toTime(now));
  if (!plan.validation.ok())
    return reject(gh, codeOf(plan.validation.error), plan.validation.message);

  if (phase_ != Phase::Idle)
  {
    Result r;
    r.error_string = "preempted by a newer goal";
    active_.setCanceled(r, r.error_string);
  }
  gh.setAccepted();
  if (measured)
    arm_.adopt(realArm());  // the preview starts where the real arm is
  arm_.start(plan, tolerances, toTime(now));
  goal_start_ = plan.start;
  active_ = gh;
  phase_ = Phase::Simulating;
  last_feedback_ = ros::Time();
}

void ArmActionServer::onCancel(GoalHandle gh)
{
  if (phase_ == Phase::Idle || !(gh == active_))
    return;
  if (phase_ == Phase::Simulating)
    arm_.stop(toTime(options_.clock()));  // a smooth stop within the acceleration limits
  if (phase_ == Phase::Relaying)
    relay_->cancel();  // the real arm stops where its driver stops it; the result says the cancel was forwarded
  Result r;
  r.error_string = phase_ == Phase::Relaying ? "canceled; cancel forwarded to the real driver" : "canceled";
  active_.setCanceled(r, r.error_string);
  phase_ = Phase::Idle;
}

void ArmActionServer::preempt(const std::string& why)
{
  if (phase_ != Phase::Simulating && phase_ != Phase::AwaitingConfirmation)
    return;
  Result r;
  r.error_string = why;
  active_.setCanceled(r, why);
  phase_ = Phase::Idle;
}

void ArmActionServer::suspend(const std::string& why)
{
  if (suspended_)
    return;
  suspended_ = true;
  ROS_ERROR_STREAM(name_ << ": " << why);
  if (phase_ == Phase::Simulating || phase_ == Phase::AwaitingConfirmation)
    finish(Result::PATH_TOLERANCE_VIOLATED, "aborted: " + why);
  arm_.release();
}

void ArmActionServer::setFreeDrive(bool active, const ros::Time& now)
{
  if (active == free_drive_)
    return;
  free_drive_ = active;
  ROS_INFO_STREAM(name_ << ": free-drive " << (active ? "on" : "off"));
  if (active && (phase_ == Phase::Simulating || phase_ == Phase::AwaitingConfirmation))
    finish(Result::PATH_TOLERANCE_VIOLATED, std::string("aborted: ") + kFreeDrive);
  if (hw_.measures())
  {
    // the compliant arm is wherever the operator put it: hold that, never an older target
    arm_.holdMeasured();
    arm_.followMeasured(active);
  }
  else if (arm_.moving())
    arm_.stop(toTime(now));
}

bool ArmActionServer::onConfirm(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res)
{
  if (phase_ != Phase::AwaitingConfirmation)
  {
    res.success = false;
    res.message = phase_ == Phase::Simulating ? "the goal is still running in simulation" :
                  phase_ == Phase::Relaying   ? "the goal was already relayed" :
                                                "no goal awaits confirmation";
    return true;
  }
  // The relay's callbacks arrive until the driver's goal ends; a goal of ours that was cancelled or replaced
  // meanwhile (another id, or no longer relaying) ignores them.
  const std::string id = active_.getGoalID().id;
  const auto done = [this, id](const actionlib::SimpleClientGoalState& state, const Result& result) {
    if (phase_ != Phase::Relaying || active_.getGoalID().id != id)
      return;
    if (state == actionlib::SimpleClientGoalState::SUCCEEDED)
      active_.setSucceeded(result, result.error_string);
    else
      active_.setAborted(result, "real driver: " + state.toString() + " " + result.error_string);
    phase_ = Phase::Idle;
  };
  const auto feedback = [this, id](const control_msgs::FollowJointTrajectoryFeedback& f) {
    if (phase_ != Phase::Relaying || active_.getGoalID().id != id)
      return;
    auto out = f;
    for (auto& n : out.joint_names)
      n = relay_->prefixed(n);
    active_.publishFeedback(out);
  };
  if (!relay_->send(*active_.getGoal(), done, feedback))
  {
    res.success = false;
    res.message = "real driver action " + relay_->action() + " is not connected; nothing was sent";
    return true;
  }
  phase_ = Phase::Relaying;
  res.success = true;
  res.message = "goal " + id + " relayed to " + relay_->action();
  ROS_INFO_STREAM(name_ << ": " << res.message);
  return true;
}

std::vector<double> ArmActionServer::realArm() const
{
  std::vector<double> q;
  for (const auto& j : arm_.joints())
    q.push_back(real_->state().positions[real_->index(j)]);
  return q;
}

void ArmActionServer::publishFeedback(const ros::Time& now, const ArmController::Cycle& cycle)
{
  control_msgs::FollowJointTrajectoryFeedback f;
  f.header.stamp = now;
  f.joint_names = arm_.joints();
  const double elapsed = std::max(0.0, toTime(now) - goal_start_);  // time_from_start, as joint_trajectory_controller
  f.desired = toPointMsg(cycle.desired, elapsed);
  f.actual = toPointMsg(cycle.actual, elapsed);
  f.error = toPointMsg(cycle.error, elapsed);
  active_.publishFeedback(f);
}

void ArmActionServer::update(const ros::Time& now)
{
  if (suspended_ && updated_)
    ROS_INFO_STREAM(name_ << ": running again; holding the measured pose");
  suspended_ = false;
  updated_ = true;
  // Real mode: unless a goal is previewed, the virtual arm is where the real one is (the next preview and gate
  // start there).
  if (real_ && real_->ready() && (phase_ == Phase::Idle || phase_ == Phase::Relaying))
    arm_.adopt(realArm());
  const ArmController::Cycle c = arm_.update(toTime(now));
  server_.heartbeat(now);
  // The phases: Simulating (fake, physics, and real mode's preview) ends in a result, or in real mode waits for
  // the confirmation; Relaying ends by the driver's result (onConfirm's callbacks) or its disconnection.
  if (phase_ == Phase::Simulating)
  {
    // feedback at the period asked for, and always with the cycle that ends the goal
    if (c.outcome != ArmController::Outcome::None || last_feedback_.isZero() ||
        (now - last_feedback_).toSec() >= options_.feedback_period - 1e-9)
    {
      publishFeedback(now, c);
      last_feedback_ = now;
    }
    switch (c.outcome)
    {
      case ArmController::Outcome::None:
        break;
      case ArmController::Outcome::Succeeded:
        if (!relay_)
          return finish(Result::SUCCESSFUL, "");
        phase_ = Phase::AwaitingConfirmation;
        confirm_deadline_ = now + ros::Duration(options_.confirm_timeout);
        ROS_INFO_STREAM(name_ << ": goal ran in simulation; call " << confirm_.getService()
                              << " to send it to " << relay_->action());
        break;
      case ArmController::Outcome::PathToleranceViolated:
        return finish(Result::PATH_TOLERANCE_VIOLATED, c.message);
      case ArmController::Outcome::GoalToleranceViolated:
        return finish(Result::GOAL_TOLERANCE_VIOLATED, c.message);
    }
  }
  else if (phase_ == Phase::Relaying && !relay_->connected())
    finish(Result::PATH_TOLERANCE_VIOLATED, "real driver " + relay_->action() +
                                                " went away during the goal; where the real arm stopped is unknown");
  else if (phase_ == Phase::AwaitingConfirmation && now > confirm_deadline_)
    finish(Result::INVALID_GOAL, "no confirmation within " + std::to_string(options_.confirm_timeout) +
                                     " s; nothing was sent to the real robot");
}
}  // namespace vrrw_control
