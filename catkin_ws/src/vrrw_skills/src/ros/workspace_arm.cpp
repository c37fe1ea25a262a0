#include <vrrw_skills/ros/workspace_arm.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include <std_srvs/Trigger.h>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_kinematics/kinematics_error.h>
#include <vrrw_kinematics/robot_model.h>
#include <vrrw_scene/robot_config.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_skills
{
namespace
{
/// s of simulated time a goal may run past its trajectory's end before it counts as hung.
constexpr double kResultMargin = 30.0;

/// Wall seconds a stop may take to reach this process (joint state, tf): far beyond a loaded machine, short of a hang.
constexpr double kCatchUpSeconds = 10.0;
/// Simulated s per step call while a goal runs: a stop between them checks for an interrupt.
constexpr double kSlice = 0.25;

/// Set by interrupt() (a signal handler): the waits cancel their goal and end.
std::atomic<bool> interrupted{ false };

std::vector<std::string> sceneRobots(ros::NodeHandle& node)
{
  std::vector<std::string> names;
  XmlRpc::XmlRpcValue robots;
  if (node.getParam("/scene/robots", robots) && robots.getType() == XmlRpc::XmlRpcValue::TypeStruct)
    for (const auto& entry : robots)
      names.push_back(entry.first);
  return names;
}
}  // namespace

WorkspaceArm::WorkspaceArm(ros::NodeHandle& node, const std::string& robot, vrrw_common::PersistentServices& services)
  : robot_(robot)
  , services_(services)
  , tf_buffer_(ros::Duration(60.0))
  , tf_listener_(tf_buffer_)
  , arm_("/" + robot + "/arm_controller/follow_joint_trajectory")
  , gripper_("/" + robot + "/gripper_controller/gripper_cmd")
{
  const std::string params = "/scene/robots/" + robot + "/";
  if (!node.getParam(params + "arm_joints", arm_joints_) || arm_joints_.empty())
  {
    std::string known;
    for (const std::string& name : sceneRobots(node))
      known += (known.empty() ? "" : ", ") + name;
    throw SkillError("--robot " + robot + ": not a robot of the running workspace (robots: " +
                     (known.empty() ? "none" : known) + ")");
  }
  node.getParam(params + "tcp_link", tcp_link_);
  node.param<std::string>("/" + robot + "/controller/mode", mode_, "fake");
  std::string urdf;
  node.getParam("/robot_description", urdf);
  try
  {
    const auto model = vrrw_kinematics::RobotModel::fromUrdf(urdf);
    for (const std::string& joint : arm_joints_)
      max_velocity_.push_back(model.joints()[static_cast<std::size_t>(model.jointIndex(joint))].max_velocity);
  }
  catch (const vrrw_kinematics::KinematicsError& e)
  {
    throw SkillError("/robot_description: " + std::string(e.what()));
  }
  std::string config;
  if (node.getParam(params + "config_file", config) && !config.empty())
  {
    try
    {
      const auto limits = vrrw_scene::loadAccelerationLimits(config, robot + "_");
      for (const std::string& joint : arm_joints_)
        max_acceleration_.push_back(limits.count(joint) ? limits.at(joint) : 0.0);
    }
    catch (const std::exception& e)
    {
      throw SkillError(params + "config_file: " + e.what());
    }
  }
  joint_states_ = node.subscribe("/" + robot + "/joint_states", 10, &WorkspaceArm::onJointStates, this);
}

WorkspaceArm::~WorkspaceArm()
{
  if (sim_)
    sim_->removeStopObserver(stop_observer_);
}

void WorkspaceArm::holdSimulation(vrrw_physics::LockstepClient& sim)
{
  sim_ = &sim;
  stop_observer_ = sim.addStopObserver([this](const ros::Time& time) { catchUp(time); });
}

void WorkspaceArm::catchUp(const ros::Time& time)
{
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kCatchUpSeconds);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!state_arrived_.wait_until(lock, deadline, [&] { return stamp_ >= time; }))
      throw SkillRefusal("/" + robot_ + "/joint_states: no state at the simulation's stop (" +
                         std::to_string(time.toSec()) + " s) within " + std::to_string(int(kCatchUpSeconds)) + " s");
  }
  std::vector<std::string> frames = watched_;
  frames.push_back(tcp_link_);
  for (const std::string& frame : frames)  // tf at the stop's stamp: every earlier one arrived too (in order)
    while (!tf_buffer_.canTransform("world", frame, time))
    {
      if (std::chrono::steady_clock::now() > deadline)
        throw SkillRefusal("tf: no '" + frame + "' at the simulation's stop (" + std::to_string(time.toSec()) + " s)");
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

void WorkspaceArm::onJointStates(const sensor_msgs::JointState::ConstPtr& message)
{
  const auto mapping = vrrw_common::findJoints(message->name, arm_joints_);
  if (!mapping || message->position.size() != message->name.size())
    return;
  std::vector<double> q(arm_joints_.size());
  double fastest = 0.0;
  for (std::size_t j = 0; j < q.size(); ++j)
  {
    q[j] = message->position[(*mapping)[j]];
    if (message->velocity.size() == message->name.size())
      fastest = std::max(fastest, std::abs(message->velocity[(*mapping)[j]]));
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = std::move(q);
    speed_ = fastest;
    stamp_ = message->header.stamp;
  }
  state_arrived_.notify_all();
}

void WorkspaceArm::waitUntilReady(double seconds)
{
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && joints().empty() && ros::WallTime::now() < end)
    ros::WallDuration(0.01).sleep();
  if (joints().empty())
    throw SkillRefusal("/" + robot_ + "/joint_states: no state of the arm within " + std::to_string(int(seconds)) +
                       " s");
  while (ros::ok() && !(arm_.isServerConnected() && gripper_.isServerConnected()) && ros::WallTime::now() < end)
    ros::WallDuration(0.01).sleep();
  if (!arm_.isServerConnected() || !gripper_.isServerConnected())
    throw SkillRefusal("/" + robot_ + ": its arm or gripper controller does not answer");
}

std::vector<double> WorkspaceArm::joints() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return latest_;
}

double WorkspaceArm::speed() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return speed_;
}

std::optional<CartesianPose> WorkspaceArm::pose(const std::string& frame) const
{
  return poseAt(frame, ros::Time(0));
}

std::optional<CartesianPose> WorkspaceArm::poseAt(const std::string& frame, const ros::Time& time) const
{
  try
  {
    return toPose(tf2::transformToEigen(tf_buffer_.lookupTransform("world", frame, time)));
  }
  catch (const tf2::TransformException&)
  {
    return std::nullopt;
  }
}

ros::Time WorkspaceArm::now() const
{
  return sim_ ? sim_->time() : ros::Time::now();
}

void WorkspaceArm::settle(double seconds)
{
  if (!sim_)
    return ros::Duration(seconds).sleep(), void();
  try
  {
    sim_->step(seconds);
  }
  catch (const vrrw_physics::LockstepError& e)
  {
    throw SkillRefusal(e.what());
  }
}

void WorkspaceArm::confirmReal(const std::string& instruction, double seconds)
{
  // the controller runs the goal in simulation, then holds it until confirmed ("still running in simulation"
  // before that): the operator said yes to the run already
  const std::string service = "/" + robot_ + "/arm_controller/confirm_real_execution";
  std_srvs::Trigger confirm;
  for (const ros::Time end = ros::Time::now() + ros::Duration(seconds); ros::ok() && !interrupted && ros::Time::now() < end;
       ros::WallDuration(0.05).sleep())
    if (services_.tryCall(service, confirm) && confirm.response.success)
      return;
  throw SkillRefusal(instruction + ": " + service + ": not confirmed (" + confirm.response.message + ")");
}

void WorkspaceArm::interrupt()
{
  interrupted = true;
}

template <class Client>
void WorkspaceArm::waitFor(Client& client, const std::string& instruction, const std::string& what, double seconds)
{
  const ros::Time end = ros::Time::now() + ros::Duration(seconds);
  while (!client.getState().isDone())
  {
    if (interrupted || !ros::ok())
    {
      client.cancelGoal();
      throw SkillRefusal(instruction + ": interrupted; the " + what + " goal was cancelled");
    }
    if (ros::Time::now() > end)
    {
      client.cancelGoal();
      throw SkillRefusal(instruction + ": the " + what + " controller gave no result within " +
                         std::to_string(int(seconds)) + " s");
    }
    ros::WallDuration(0.005).sleep();
  }
}

template <class Client>
void WorkspaceArm::stepUntilDone(Client& client, const std::string& instruction, const std::string& what,
                                 double seconds)
{
  if (!vrrw_physics::waitUntilAccepted(client, kCatchUpSeconds))
  {
    client.cancelGoal();
    throw SkillRefusal(instruction + ": the " + what + " controller did not take the goal within " +
                       std::to_string(int(kCatchUpSeconds)) + " s");
  }
  try
  {
    bool idle = false;
    for (double left = seconds; !idle && left > 0.0; left -= kSlice)
    {
      if (interrupted || !ros::ok())
      {
        client.cancelGoal();
        throw SkillRefusal(instruction + ": interrupted; the " + what + " goal was cancelled");
      }
      idle = sim_->stepUntilIdle(std::min(left, kSlice));
    }
    if (!idle)
    {
      client.cancelGoal();
      throw SkillRefusal(instruction + ": the " + what + " controller gave no result within " +
                         std::to_string(int(seconds)) + " s");
    }
  }
  catch (const vrrw_physics::LockstepError& e)
  {
    client.cancelGoal();
    throw SkillRefusal(instruction + ": " + e.what());
  }
  if (!vrrw_physics::waitUntilDone(client, kCatchUpSeconds))
    throw SkillRefusal(instruction + ": the " + what + " controller ended the goal but its result did not arrive");
}

void WorkspaceArm::execute(const std::string& instruction, const vrrw_trajectory::JointTrajectory& trajectory,
                           double goal_tolerance)
{
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = vrrw_trajectory::toMsg(trajectory);
  if (goal_tolerance > 0.0)
    for (const std::string& joint : goal.trajectory.joint_names)
    {
      control_msgs::JointTolerance tolerance;
      tolerance.name = joint;
      tolerance.position = goal_tolerance;
      goal.goal_tolerance.push_back(tolerance);
    }
  arm_.sendGoal(goal);
  const double timeout = trajectory.duration() + kResultMargin;
  if (mode_ == "real")
    confirmReal(instruction, timeout);
  if (sim_)
    stepUntilDone(arm_, instruction, "arm", timeout);
  else
    waitFor(arm_, instruction, "arm", timeout);
  const auto result = arm_.getResult();
  if (arm_.getState() != actionlib::SimpleClientGoalState::SUCCEEDED || (result && result->error_code != 0))
    throw SkillRefusal(instruction + ": the arm controller answered " + arm_.getState().toString() +
                       (result && !result->error_string.empty() ? ": " + result->error_string : ""));
}

void WorkspaceArm::grip(const std::string& instruction, double position, double max_effort)
{
  control_msgs::GripperCommandGoal goal;
  goal.command.position = position;
  goal.command.max_effort = max_effort;
  if (sim_)
    sim_->awaitClock();  // the goal's stamp is the ROS clock: the instant the simulation waits at
  gripper_.sendGoal(goal);
  if (sim_)
    stepUntilDone(gripper_, instruction, "gripper", kResultMargin);
  else
    waitFor(gripper_, instruction, "gripper", kResultMargin);
  if (gripper_.getState() != actionlib::SimpleClientGoalState::SUCCEEDED)
    throw SkillRefusal(instruction + ": the gripper controller answered " + gripper_.getState().toString() + " " +
                       gripper_.getState().getText());
}
}  // namespace vrrw_skills
