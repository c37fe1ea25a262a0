#include "workspace_client.h"

#include <std_srvs/Trigger.h>

#include <tf2_eigen/tf2_eigen.h>
#include <cstdio>
#include <stdexcept>
#include <vrrw_msgs/ComputeIK.h>
#include <vrrw_msgs/DemoAnnotate.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStop.h>
#include <vrrw_msgs/Plan.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_skills/trial_outcome.h>

namespace vrrw_evaluation
{
namespace
{
const std::string kPlace = "/physics/set_object_pose";
/// The track's sampling period (simulated s): the top view's and the lift test's 20 Hz.
constexpr double kTrackPeriod = 0.05;

trajectory_msgs::JointTrajectory toMsg(const vrrw_trajectory::JointTrajectory& trajectory)
{
  trajectory_msgs::JointTrajectory msg;
  msg.joint_names = trajectory.joint_names;
  for (const auto& p : trajectory.points)
  {
    trajectory_msgs::JointTrajectoryPoint point;
    point.positions = p.positions;
    point.velocities = p.velocities;
    point.time_from_start = ros::Duration(p.time);
    msg.points.push_back(point);
  }
  return msg;
}

sensor_msgs::JointState jointState(const std::vector<std::string>& names, const std::vector<double>& q)
{
  sensor_msgs::JointState state;
  state.name = names;
  state.position = q;
  return state;
}
}  // namespace

WorkspaceClient::WorkspaceClient(ros::NodeHandle& node, const vrrw_scene::Robot& robot, const std::string& object,
                                 std::set<std::string> obstacles, vrrw_physics::LockstepClient& sim)
  : robot_(robot)
  , object_(object)
  , obstacles_(std::move(obstacles))
  , node_(node)
  , sim_(sim)
  , tf_buffer_(ros::Duration(600.0))  // a run's track is looked up in simulated time that lies up to minutes back
  , tf_listener_(tf_buffer_)
  , arm_("/" + robot.name + "/arm_controller/follow_joint_trajectory")
  , gripper_("/" + robot.name + "/gripper_controller/gripper_cmd")
  , ik_("/" + robot.name + "/compute_ik")
  , plan_("/" + robot.name + "/plan")
{
  // Queues far beyond what one step slice publishes (0.25 s at 100 Hz): nothing is dropped, so every run records
  // the same messages.
  joint_states_ = node.subscribe("/" + robot.name + "/joint_states", 1000, &WorkspaceClient::onJointStates, this);
  contacts_ = node.subscribe("/physics/contacts", 1000, &WorkspaceClient::onContacts, this);
  stop_observer_ = sim_.addStopObserver([this](const ros::Time& time) { catchUp(time); });
}

WorkspaceClient::~WorkspaceClient()
{
  sim_.removeStopObserver(stop_observer_);
}

bool WorkspaceClient::waitUntilReady(double seconds, std::string& error)
{
  // Every wait here is on the wall clock: ROS time stands still while the simulation waits.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  auto left = [&] { return std::max(0.01, (deadline - ros::WallTime::now()).toSec()); };
  auto connected = [&] {
    for (; ros::WallTime::now() < deadline; ros::WallDuration(0.01).sleep())
      if (arm_.isServerConnected() && gripper_.isServerConnected())
        return true;
    return false;
  };
  if (!sim_.waitForPhysics(left()))
    return error = "no physics node (/physics/step): the demo runs in physics mode", false;
  if (!connected())
    return error = "no controller for " + robot_.name + " (arm_controller / gripper_controller)", false;
  if (!vrrw_common::PersistentServices::waitFor(ik_, left()) || !vrrw_common::PersistentServices::waitFor(plan_, left()))
    return error = "no planning node (/" + robot_.name + "/compute_ik, /plan)", false;
  std::string urdf;
  if (!node_.getParam("/robot_description", urdf))
    return error = "no /robot_description", false;
  auto model = vrrw_kinematics::RobotModel::fromUrdf(urdf);
  max_velocity_.clear();
  for (const std::string& joint : robot_.arm_joints)
  {
    const int index = model.jointIndex(joint);
    if (index < 0)
      return error = "/robot_description has no joint " + joint, false;
    max_velocity_.push_back(model.joints()[std::size_t(index)].max_velocity);
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    model_ = std::move(model);
  }
  // Physics published its paused start once, before anyone listened: the first step publishes the state where it
  // waits again, once this client's subscribers are connected (tf's listener connects beside them: a second more).
  for (; joint_states_.getNumPublishers() == 0 || contacts_.getNumPublishers() == 0; ros::WallDuration(0.01).sleep())
    if (ros::WallTime::now() > deadline)
      return error = "no /" + robot_.name + "/joint_states or /physics/contacts from the physics node", false;
  ros::WallDuration(1.0).sleep();
  try
  {
    sim_.pause();  // (the workspace starts paused for the demo; a second pause changes nothing)
    sim_.step(0.001);
  }
  catch (const std::runtime_error& e)
  {
    return error = e.what(), false;
  }
  ready_sim_ = sim_.time();
  ready_wall_ = ros::WallTime::now();
  return true;
}

void WorkspaceClient::catchUp(const ros::Time& time)
{
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kAnswerSeconds);
  std::unique_lock<std::mutex> lock(mutex_);
  if (!state_arrived_.wait_until(lock, deadline, [&] { return latest_.header.stamp >= time; }))
    throw std::runtime_error("/" + robot_.name + "/joint_states: no state at " + std::to_string(time.toSec()) +
                             " s within " + std::to_string(int(kAnswerSeconds)) + " s of the step's end");
  if (!contacts_arrived_.wait_until(lock, deadline, [&] { return contacts_stamp_ >= time; }))
    throw std::runtime_error("/physics/contacts: none at " + std::to_string(time.toSec()) + " s within " +
                             std::to_string(int(kAnswerSeconds)) + " s of the step's end");
  lock.unlock();
  // tf of the object at exactly the stop's stamp: then every earlier one arrived too (one publisher, in order)
  for (int k = 0; !tf_buffer_.canTransform("world", object_, time); ++k)
  {
    if (k >= int(kAnswerSeconds * 1000))
      throw std::runtime_error("tf: no '" + object_ + "' at " + std::to_string(time.toSec()) + " s");
    ros::WallDuration(0.001).sleep();
  }
  lock.lock();
  const std::size_t first = recording_data_.track.size() - unresolved_.size();
  for (std::size_t i = 0; i < unresolved_.size(); ++i)
    recording_data_.track[first + i].object = lookup(object_, unresolved_[i]).value_or(Eigen::Isometry3d::Identity());
  unresolved_.clear();
}

std::vector<double> WorkspaceClient::armJoints()
{
  std::lock_guard<std::mutex> lock(mutex_);
  return latest_arm_;
}

std::optional<Eigen::Isometry3d> WorkspaceClient::lookup(const std::string& frame, const ros::Time& time)
{
  try
  {
    return tf2::transformToEigen(tf_buffer_.lookupTransform("world", frame, time));
  }
  catch (const tf2::TransformException&)
  {
    return std::nullopt;
  }
}

Eigen::Isometry3d WorkspaceClient::objectPose()
{
  return lookup(object_, sim_.time()).value_or(Eigen::Isometry3d::Identity());
}

Eigen::Isometry3d WorkspaceClient::linkPose(const sensor_msgs::JointState& state, const std::string& link) const
{
  Eigen::VectorXd q = model_->neutralState();
  for (std::size_t i = 0; i < state.name.size() && i < state.position.size(); ++i)
    if (const int v = model_->variableIndex(state.name[i]); v >= 0)
      q[v] = state.position[i];
  return model_->relativeTransform(q, model_->links()[0].name, link);
}

Eigen::Isometry3d WorkspaceClient::tcpPose()
{
  std::lock_guard<std::mutex> lock(mutex_);
  return linkPose(latest_, robot_.tcp_link);
}

Eigen::Isometry3d WorkspaceClient::flangePose()
{
  std::lock_guard<std::mutex> lock(mutex_);
  return linkPose(latest_, robot_.tool_link);
}

bool WorkspaceClient::execute(const vrrw_trajectory::JointTrajectory& trajectory, std::string& error)
{
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = toMsg(trajectory);  // stamp zero: it starts where the simulation waits
  arm_.sendGoal(goal);
  if (!vrrw_physics::waitUntilAccepted(arm_, kAnswerSeconds))
    return arm_.cancelGoal(), error = "the arm controller did not take the goal within 10 s", false;
  if (!sim_.stepUntilIdle(trajectory.duration() + 10.0))
    return arm_.cancelGoal(), error = "no result within the trajectory's duration + 10 s", false;
  if (!vrrw_physics::waitUntilDone(arm_, kAnswerSeconds))
    return error = "the arm controller ended the goal but its result did not arrive", false;
  if (arm_.getState() == actionlib::SimpleClientGoalState::SUCCEEDED)
    return true;
  error = "arm goal " + arm_.getState().toString() + ": " + arm_.getResult()->error_string;
  return false;
}

bool WorkspaceClient::grip(double position, double max_effort, std::string& error)
{
  control_msgs::GripperCommandGoal goal;
  goal.command.position = position;
  goal.command.max_effort = max_effort;
  sim_.awaitClock();  // the goal's stamp (the ROS clock) is what a demonstration's learner reads
  gripper_.sendGoal(goal);
  if (!vrrw_physics::waitUntilAccepted(gripper_, kAnswerSeconds))
    return gripper_.cancelGoal(), error = "gripper: the controller did not take the goal within 10 s", false;
  if (!sim_.stepUntilIdle(10.0))
    return gripper_.cancelGoal(), error = "gripper: no result within 10 s", false;
  if (!vrrw_physics::waitUntilDone(gripper_, kAnswerSeconds))
    return error = "gripper: the controller ended the goal but its result did not arrive", false;
  if (gripper_.getState() == actionlib::SimpleClientGoalState::SUCCEEDED)
    return true;
  error = "gripper goal " + gripper_.getState().toString() + " " + gripper_.getState().getText();
  return false;
}

std::optional<std::vector<double>> WorkspaceClient::ik(const Eigen::Isometry3d& tcp, const std::vector<double>& seed,
                                                       bool avoid_collisions, std::string& error, double* ik_ms)
{
  vrrw_msgs::ComputeIK srv;
  srv.request.pose.header.frame_id = "world";
  srv.request.pose.pose = tf2::toMsg(tcp);
  srv.request.seed = jointState(robot_.arm_joints, seed);
  srv.request.mode = vrrw_msgs::ComputeIK::Request::FULL;
  srv.request.timeout = 0.05;
  srv.request.avoid_collisions = avoid_collisions;
  const ros::WallTime start = ros::WallTime::now();
  const bool called = links_.tryCall(ik_, srv);
  if (ik_ms)
    *ik_ms += (ros::WallTime::now() - start).toSec() * 1000.0;
  if (!called)
    return error = "compute_ik did not answer", std::nullopt;
  if (srv.response.error_code != 0)
    return error = srv.response.message, std::nullopt;
  const auto& solution = srv.response.solution;
  std::vector<double> q;
  for (const std::string& joint : robot_.arm_joints)
    for (std::size_t i = 0; i < solution.name.size() && i < solution.position.size(); ++i)
      if (solution.name[i] == joint)
        q.push_back(solution.position[i]);
  if (q.size() != robot_.arm_joints.size())
    return error = "compute_ik answered without every arm joint", std::nullopt;
  return q;
}

std::optional<vrrw_trajectory::JointTrajectory> WorkspaceClient::plan(const std::vector<double>& goal,
                                                                      std::string& error, double* plan_ms)
{
  vrrw_msgs::Plan srv;
  // from the state where the simulation waits: the planner's own joint_states may lag it (a run would then
  // depend on message timing)
  srv.request.start = jointState(robot_.arm_joints, armJoints());
  srv.request.goal_joints = jointState(robot_.arm_joints, goal);
  srv.request.time_limit = 2.0;
  srv.request.seed = 1;
  if (!links_.tryCall(plan_, srv))
    return error = "plan did not answer", std::nullopt;
  if (srv.response.error_code != 0)
    return error = srv.response.message, std::nullopt;
  if (plan_ms)
    *plan_ms += srv.response.planning_time * 1000.0;
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = srv.response.trajectory.joint_names;
  for (const auto& p : srv.response.trajectory.points)
    trajectory.points.push_back({ p.time_from_start.toSec(), p.positions, p.velocities, p.accelerations });
  return trajectory;
}

bool WorkspaceClient::placeObject(const Eigen::Isometry3d& pose, std::string& error)
{
  vrrw_physics::SetObjectPose srv;
  srv.request.object = object_;
  srv.request.pose = tf2::toMsg(pose);
  if (!links_.tryCall(kPlace, srv) || !srv.response.success)
    return error = "set_object_pose: " + srv.response.message, false;
  sim_.step(0.001);
  return true;
}

void WorkspaceClient::settle(double seconds)
{
  sim_.step(seconds);
}

void WorkspaceClient::startRecording(const std::string& bag_file)
{
  if (!bag_file.empty())
  {
    std::remove(bag_file.c_str());  // the report's own bag of an earlier run (vrrw_demos never overwrites)
    vrrw_msgs::DemoStart start;
    start.request.file = bag_file;
    start.request.robots = { robot_.name };
    std::string why;
    if (!links_.tryCall("/demos/start", start, &why))
      throw std::runtime_error(why + ": the demonstration is recorded by vrrw_demos' recorder_node");
    if (!start.response.success)
      throw std::runtime_error("/demos/start: " + start.response.message);
    demos_recording_ = true;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  recording_data_ = Recording();
  recording_data_.bag_file = bag_file;
  recording_data_.arm.joint_names = robot_.arm_joints;
  record_start_ = next_sample_ = sim_.time();
  unresolved_.clear();
  recording_ = true;
}

Recording WorkspaceClient::stopRecording()
{
  std::uint64_t demos_messages = 0;
  if (demos_recording_)
  {
    // the interaction node takes the states in bursts and may be behind: what it sends up to this instant (the
    // ghost, the hands' markers) belongs in the bag
    std_srvs::Trigger sync;
    links_.tryCall("/interaction/sync", sync);
    vrrw_msgs::DemoStop stop;
    if (links_.tryCall("/demos/stop", stop) && stop.response.success)
      demos_messages = stop.response.messages;
    else
      ROS_WARN_STREAM("/demos/stop: " << stop.response.message);
    demos_recording_ = false;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  recording_ = false;
  recording_data_.bag_messages = demos_messages;
  recording_data_.seconds = (sim_.time() - record_start_).toSec();
  recording_data_.start_stamp = record_start_.toSec();
  return std::move(recording_data_);
}

void WorkspaceClient::annotate(const std::string& kind, const std::string& detail)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!recording_)
      return;
    ++recording_data_.event_messages;
  }
  if (!demos_recording_)
    return;
  vrrw_msgs::DemoAnnotate annotate;
  annotate.request.stamp = sim_.time();  // the bag's event where the simulation waits
  annotate.request.text = kind + " " + detail;
  links_.tryCall("/demos/annotate", annotate);
}

double WorkspaceClient::recordingTime() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return (sim_.time() - record_start_).toSec();
}

double WorkspaceClient::realTimeFactor() const
{
  return (sim_.time() - ready_sim_).toSec() / std::max(1e-9, (ros::WallTime::now() - ready_wall_).toSec());
}

void WorkspaceClient::onJointStates(const sensor_msgs::JointState::ConstPtr& msg)
{
  std::vector<double> q, qd;
  for (const std::string& joint : robot_.arm_joints)
    for (std::size_t i = 0; i < msg->name.size(); ++i)
      if (msg->name[i] == joint)
      {
        q.push_back(msg->position[i]);
        qd.push_back(i < msg->velocity.size() ? msg->velocity[i] : 0.0);
      }
  if (q.size() != robot_.arm_joints.size())
    return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = *msg;
    latest_arm_ = q;
    if (recording_ && msg->header.stamp > record_start_)  // (the state where it started arrived before it)
    {
      ++recording_data_.joint_state_messages;
      recording_data_.arm.points.push_back({ (msg->header.stamp - record_start_).toSec(), q, qd, {} });
      if (msg->header.stamp >= next_sample_)
      {
        // the TCP now; the object once its tf at this stamp has arrived (catchUp)
        recording_data_.track.push_back({ (msg->header.stamp - record_start_).toSec(),
                                          linkPose(*msg, robot_.tcp_link).translation(), Eigen::Isometry3d::Identity() });
        unresolved_.push_back(msg->header.stamp);
        next_sample_ = msg->header.stamp + ros::Duration(kTrackPeriod);
      }
    }
  }
  state_arrived_.notify_all();
}

void WorkspaceClient::onContacts(const vrrw_physics::Contacts::ConstPtr& msg)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    contacts_stamp_ = std::max(contacts_stamp_, msg->header.stamp);
    // after the recording's start only: the message published where it started may arrive after it
    if (recording_ && msg->header.stamp > record_start_)
    {
      ++recording_data_.contact_messages;
      for (const auto& c : msg->contacts)
        if (vrrw_skills::isArmCollision(c.body_a, c.body_b, robot_.name, obstacles_))
          recording_data_.arm_contacts.insert(c.body_a + "|" + c.body_b);
    }
  }
  contacts_arrived_.notify_all();
}
}  // namespace vrrw_evaluation
