#include <vrrw_demos/ros/robot_controllers.h>

#include <algorithm>
#include <iostream>

#include <vrrw_common/joint_mapping.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_physics/ros/lockstep_client.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_demos
{
namespace
{
/// Wall time between looks at the clock and the goals: short against a 10 ms point spacing, long enough
/// not to busy a core.
const ros::WallDuration kPoll(0.002);
/// Lockstep: simulated s per step call while nothing else is due (a progress line and a cancel between them).
constexpr double kSlice = 0.25;
/// Lockstep: wall s a controller may take to take a goal sent while the simulation waits.
constexpr double kTakeSeconds = 10.0;

}  // namespace

std::string GoalOutcome::text() const
{
  std::string out = state;
  if (error_code != 0 || !message.empty())
    out += " (" + (error_code != 0 ? "error_code " + std::to_string(error_code) + (message.empty() ? "" : ": ") : "") +
           message + ")";
  return out;
}

RobotControllers::RobotControllers(const std::string& robot, bool real, const std::atomic<bool>* interrupted)
  : ns_("/" + robot + "/")
  , real_(real)
  , interrupted_(interrupted)
  , arm_(ns_ + "arm_controller/follow_joint_trajectory")
  , gripper_(ns_ + "gripper_controller/gripper_cmd")
  , services_(std::make_unique<vrrw_common::PersistentServices>())
{
  states_ = ros::NodeHandle().subscribe<sensor_msgs::JointState>(
      ns_ + "joint_states", 1, [this](const sensor_msgs::JointStateConstPtr& state) {
        std::lock_guard<std::mutex> lock(state_mutex_);
        latest_state_ = *state;
        ++states_seen_;
      });
}

RobotControllers::~RobotControllers() = default;

void RobotControllers::connect(double seconds)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  const auto left = [&] { return std::max(0.01, (end - ros::WallTime::now()).toSec()); };
  // waitForServer's timeout is on the ROS clock, which may not run yet: look in wall slices (the clients
  // connect on their own spin threads)
  while (!arm_.isServerConnected() && ros::WallTime::now() < end && !cancelled())
    kPoll.sleep();
  if (!arm_.isServerConnected())
    throw DemoError(ns_ + "arm_controller/follow_joint_trajectory: no action server within " +
                    std::to_string(static_cast<int>(seconds)) + " s (is the robot's controller running?)");
  while (!gripper_.isServerConnected() && ros::WallTime::now() < end && !cancelled())
    kPoll.sleep();
  if (!gripper_.isServerConnected())
    throw DemoError(ns_ + "gripper_controller/gripper_cmd: no action server (is the robot's controller running?)");
  if (!real_)
    return;
  const std::string service = ns_ + "arm_controller/confirm_real_execution";
  if (!vrrw_common::PersistentServices::waitFor(service, left()))
    throw DemoError(service + ": not advertised (is the controller in real mode?)");
  confirm_service_ = service;
}

std::vector<double> RobotControllers::measuredArm(const std::vector<std::string>& joints, double seconds)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  const std::size_t seen = states_seen_;
  while (ros::WallTime::now() < end && !cancelled())
  {
    {
      std::lock_guard<std::mutex> lock(state_mutex_);
      // a state newer than the call; in lockstep the one published where the simulation waits
      if (states_seen_ > seen || (sim_ && latest_state_.header.stamp >= sim_->time()))
      {
        if (const auto q = vrrw_common::findValues(latest_state_.name, latest_state_.position, joints))
          return *q;
      }
    }
    kPoll.sleep();
  }
  throw DemoError(ns_ + "joint_states: none with every arm joint within " + std::to_string(seconds) + " s");
}

bool RobotControllers::waitUntilAt(const std::vector<std::string>& joints, const std::vector<double>& q,
                                   double tolerance, double seconds)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::WallTime::now() < end && !cancelled())
  {
    const std::vector<double> now = measuredArm(joints, seconds);
    double farthest = 0.0;
    for (std::size_t j = 0; j < q.size() && j < now.size(); ++j)
      farthest = std::max(farthest, std::abs(now[j] - q[j]));
    if (farthest < tolerance)
      return true;
  }
  return false;
}

ros::Time RobotControllers::now() const
{
  return sim_ ? sim_->time() : ros::Time::now();
}

template <class Client>
bool RobotControllers::taken(Client& client)
{
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kTakeSeconds); ros::WallTime::now() < end;
       kPoll.sleep())
    if (client.getState() != actionlib::SimpleClientGoalState::PENDING)
      return true;
  return false;
}

bool RobotControllers::pause(double seconds)
{
  if (sim_)
  {
    try
    {
      for (double left = seconds; left > 1e-9 && !cancelled(); left -= kSlice)
        sim_->step(std::min(left, kSlice));
    }
    catch (const vrrw_physics::LockstepError& e)
    {
      ROS_ERROR_STREAM(e.what());
      return false;
    }
    return !cancelled();
  }
  ros::Time until = ros::Time::now() + ros::Duration(seconds);
  while (!cancelled())
  {
    const ros::Time now = ros::Time::now();
    if (now >= until)
      return true;
    // /physics/reset puts the simulated clock back to 0, often after `until` was taken from the old time: the
    // pause then counts from the new time (else it waited as long as the simulation had run, 64 s seen)
    if (now < last_clock_)
      until = now + ros::Duration(seconds);
    if (now != last_clock_)
    {
      last_clock_ = now;
      last_clock_wall_ = ros::WallTime::now();
    }
    else if ((ros::WallTime::now() - last_clock_wall_).toSec() > kClockStalled)
      return false;
    kPoll.sleep();
  }
  return false;
}

bool RobotControllers::tryConfirm()
{
  std_srvs::Trigger confirm;
  std::string error;
  if (!services_->tryCall(confirm_service_, confirm, &error))
    confirm.response.message = error;
  confirm_message_ = confirm.response.message;
  return confirm.response.success;
}

GoalOutcome RobotControllers::armOutcome()
{
  const auto state = arm_.getState();
  GoalOutcome outcome{ state.toString(), 0, state.getText() };
  if (const auto result = arm_.getResult())
  {
    outcome.error_code = result->error_code;
    // the status text says more when it holds the result's string (a relayed goal: "real driver: ABORTED ...")
    if (!result->error_string.empty() && outcome.message.find(result->error_string) == std::string::npos)
      outcome.message = result->error_string;
  }
  return outcome;
}

GoalOutcome RobotControllers::runArm(const ArmMotion& motion, double slack, const Progress& progress)
{
  if (sim_ && !real_)
    return runArmLockstep(motion, slack, progress);
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = vrrw_trajectory::toMsg(motion.trajectory);
  goal.trajectory.header.stamp = motion.start;
  last_clock_ = ros::Time::now();
  last_clock_wall_ = ros::WallTime::now();
  arm_.sendGoal(goal);
  const ros::Time origin = motion.start.isZero() ? ros::Time::now() : motion.start;
  const double duration = motion.trajectory.duration();
  ros::Time deadline = origin + ros::Duration(duration + slack);
  ros::Time real_start;  // real mode: when the controller relayed the goal to the driver
  ros::WallTime shown = ros::WallTime::now();
  ros::Time next_confirm = ros::Time::now();
  std::size_t next_gripper = 0;
  bool gripper_sent = false;
  // Cancels both goals and says what the controller made of the arm's (up to 2 s for its answer).
  const auto cancelAll = [&](const std::string& state, const std::string& why) {
    arm_.cancelGoal();
    if (gripper_sent)
      gripper_.cancelGoal();
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(2.0);
         !arm_.getState().isDone() && ros::WallTime::now() < end;)
      kPoll.sleep();
    const GoalOutcome arm = armOutcome();
    return GoalOutcome{ state, arm.error_code, why + "; the controller: " + arm.text() };
  };

  // The motion's timeline: gripper goals when the clock reaches them; in real mode the controller
  // simulates the goal meanwhile and answers "still running in simulation" until it may be confirmed.
  while (!arm_.getState().isDone())
  {
    // look every 10 ms of the ROS clock, or sooner when a gripper goal is due then
    double look = 0.01;
    if (next_gripper < motion.gripper_goals.size())
      look = std::clamp(motion.gripper_goals[next_gripper].time - (ros::Time::now() - origin).toSec(), 0.0, look);
    if (!pause(look))
      return cancelAll(cancelled() ? "CANCELLED" : "TIMEOUT",
                       cancelled() ? "cancelled by the user" : "the ROS clock stopped (is the physics node running?)");
    const ros::Time now = ros::Time::now();
    const double elapsed = (now - origin).toSec();
    for (; next_gripper < motion.gripper_goals.size() && motion.gripper_goals[next_gripper].time <= elapsed;
         ++next_gripper, gripper_sent = true)
    {
      control_msgs::GripperCommandGoal g;
      g.command.position = motion.gripper_goals[next_gripper].position;
      g.command.max_effort = motion.gripper_goals[next_gripper].effort;
      gripper_.sendGoal(g);
    }
    if (real_ && real_start.isZero() && now >= next_confirm)
    {
      next_confirm = now + ros::Duration(kConfirmPeriod);
      if (tryConfirm())
      {
        real_start = now;
        deadline = now + ros::Duration(duration + slack);
      }
    }
    if (progress && (ros::WallTime::now() - shown).toSec() >= 1.0)
    {
      shown = ros::WallTime::now();
      const bool moving_real = !real_start.isZero();
      progress({ motion.name, (now - (moving_real ? real_start : origin)).toSec(), duration, moving_real });
    }
    if (now > deadline)
      return cancelAll("TIMEOUT", "no result " + std::to_string(slack) + " s after the motion's end; cancelled" +
                                      (real_ && real_start.isZero() ? " (not confirmed: " + confirm_message_ + ")" : ""));
  }
  GoalOutcome outcome = armOutcome();
  if (real_ && real_start.isZero() && !outcome.succeeded())
    outcome.message += (outcome.message.empty() ? "" : "; ") + std::string("nothing was sent to the real robot");

  // Gripper goals after the arm's last point (a demonstration may end with the gripper opening), then
  // the last gripper goal's end.
  while (outcome.succeeded() && next_gripper < motion.gripper_goals.size())
  {
    const double wait = motion.gripper_goals[next_gripper].time - (ros::Time::now() - origin).toSec();
    if (wait > 0.0 && !pause(wait))
      return cancelAll(cancelled() ? "CANCELLED" : "TIMEOUT", cancelled() ? "cancelled by the user" : "the ROS clock stopped");
    control_msgs::GripperCommandGoal g;
    g.command.position = motion.gripper_goals[next_gripper].position;
    g.command.max_effort = motion.gripper_goals[next_gripper].effort;
    gripper_.sendGoal(g);
    gripper_sent = true;
    ++next_gripper;
  }
  for (int k = 0; gripper_sent && !gripper_.getState().isDone() && k < 1000; ++k)
    if (!pause(0.01))
      break;
  return outcome;
}

GoalOutcome RobotControllers::runArmLockstep(const ArmMotion& motion, double slack, const Progress& progress)
{
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = vrrw_trajectory::toMsg(motion.trajectory);
  goal.trajectory.header.stamp = motion.start;  // ahead of where the simulation waits: it starts there
  arm_.sendGoal(goal);
  if (!taken(arm_))
    return arm_.cancelGoal(), GoalOutcome{ "TIMEOUT", 0, "the arm controller did not take the goal" };
  const ros::Time origin = motion.start.isZero() ? now() : motion.start;
  const double duration = motion.trajectory.duration();
  const ros::Time deadline = origin + ros::Duration(duration + slack);
  std::size_t next_gripper = 0;
  bool gripper_sent = false;
  ros::WallTime shown = ros::WallTime::now();
  const auto cancelAll = [&](const std::string& state, const std::string& why) {
    arm_.cancelGoal();
    if (gripper_sent)
      gripper_.cancelGoal();
    return GoalOutcome{ state, 0, why };
  };
  try
  {
    for (bool idle = false; !idle;)
    {
      const double elapsed = (now() - origin).toSec();
      for (; next_gripper < motion.gripper_goals.size() && motion.gripper_goals[next_gripper].time <= elapsed + 1e-9;
           ++next_gripper, gripper_sent = true)
      {
        control_msgs::GripperCommandGoal g;
        g.command.position = motion.gripper_goals[next_gripper].position;
        g.command.max_effort = motion.gripper_goals[next_gripper].effort;
        gripper_.sendGoal(g);
        if (!taken(gripper_))
          return cancelAll("TIMEOUT", "the gripper controller did not take the goal");
      }
      if (cancelled())
        return cancelAll("CANCELLED", "cancelled by the user");
      if (now() > deadline)
        return cancelAll("TIMEOUT", "no result " + std::to_string(slack) + " s after the motion's end; cancelled");
      if (progress && (ros::WallTime::now() - shown).toSec() >= 1.0)
      {
        shown = ros::WallTime::now();
        progress({ motion.name, elapsed, duration, false });
      }
      // to the next gripper goal's time (whole steps: at least one), else until every controller is idle
      if (next_gripper < motion.gripper_goals.size())
        sim_->step(std::clamp(motion.gripper_goals[next_gripper].time - elapsed, 0.001, kSlice));
      else
        idle = sim_->stepUntilIdle(kSlice);
    }
  }
  catch (const vrrw_physics::LockstepError& e)
  {
    return cancelAll("TIMEOUT", e.what());
  }
  // the controllers ended their goals in the simulation; their results are on their way
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kTakeSeconds);
       (!arm_.getState().isDone() || (gripper_sent && !gripper_.getState().isDone())) && ros::WallTime::now() < end;)
    kPoll.sleep();
  return armOutcome();
}

GoalOutcome RobotControllers::runGripper(double position, double effort, double seconds)
{
  control_msgs::GripperCommandGoal goal;
  goal.command.position = position;
  goal.command.max_effort = effort;
  last_clock_ = ros::Time::now();
  last_clock_wall_ = ros::WallTime::now();
  gripper_.sendGoal(goal);
  if (sim_ && !taken(gripper_))
    return gripper_.cancelGoal(), GoalOutcome{ "TIMEOUT", 0, "the gripper controller did not take the goal" };
  const ros::Time deadline = now() + ros::Duration(seconds);
  try  // lockstep: until every controller is idle, then the result on its way (no step more)
  {
    for (bool idle = !sim_; !idle && !cancelled() && now() <= deadline;)
      idle = sim_->stepUntilIdle(kSlice);
  }
  catch (const vrrw_physics::LockstepError& e)
  {
    return gripper_.cancelGoal(), GoalOutcome{ "TIMEOUT", 0, e.what() };
  }
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kTakeSeconds);
       sim_ && !gripper_.getState().isDone() && ros::WallTime::now() < end;)
    kPoll.sleep();
  while (!gripper_.getState().isDone())
  {
    if (!pause(0.01) || now() > deadline)
    {
      gripper_.cancelGoal();
      return { cancelled() ? "CANCELLED" : "TIMEOUT", 0,
               cancelled() ? "cancelled by the user" : "no result within " + std::to_string(seconds) + " s; cancelled" };
    }
  }
  const auto state = gripper_.getState();
  return { state.toString(), 0, state.getText() };
}

bool operatorSaysYes(const std::string& question, std::istream& in, std::ostream& out)
{
  out << question << " Type yes to go on: " << std::flush;
  std::string answer;
  std::getline(in, answer);
  return answer == "yes";
}
}  // namespace vrrw_demos
