#include "workspace_client.h"

#include <vrrw_kinematics/robot_model.h>

#include <tf2_eigen/tf2_eigen.h>
#include <cstdio>
#include <stdexcept>
#include <vrrw_common/joint_mapping.h>
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
                                 std::set<std::string> obstacles)
  : robot_(robot)
  , object_(object)
  , obstacles_(std::move(obstacles))
  , node_(node)
  , tf_listener_(tf_buffer_)
  , arm_("/" + robot.name + "/arm_controller/follow_joint_trajectory", true)
  , gripper_("/" + robot.name + "/gripper_controller/gripper_cmd", true)
  , ik_("/" + robot.name + "/compute_ik")
  , plan_("/" + robot.name + "/plan")
{
  joint_states_ = node.subscribe("/" + robot.name + "/joint_states", 1000, &WorkspaceClient::onJointStates, this);
  contacts_ = node.subscribe("/physics/contacts", 100, &WorkspaceClient::onContacts, this);
  track_timer_ = node.createTimer(ros::Duration(0.05), &WorkspaceClient::onTrackTimer, this);
}

bool WorkspaceClient::waitUntilReady(double seconds, std::string& error)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  auto left = [&] { return ros::Duration(std::max(0.01, (deadline - ros::WallTime::now()).toSec())); };
  if (!arm_.waitForServer(left()) || !gripper_.waitForServer(left()))
    return error = "no controller for " + robot_.name + " (arm_controller / gripper_controller)", false;
  if (!ros::service::waitForService(ik_, left()) || !ros::service::waitForService(plan_, left()))
    return error = "no planning node (/" + robot_.name + "/compute_ik, /plan)", false;
  if (!ros::service::waitForService(kPlace, left()))
    return error = "no physics node (/physics/set_object_pose): the demo runs in physics mode", false;
  std::string urdf;
  if (!node_.getParam("/robot_description", urdf))
    return error = "no /robot_description", false;
  const auto model = vrrw_kinematics::RobotModel::fromUrdf(urdf);
  max_velocity_.clear();
  for (const std::string& joint : robot_.arm_joints)
  {
    const int index = model.jointIndex(joint);
    if (index < 0)
      return error = "/robot_description has no joint " + joint, false;
    max_velocity_.push_back(model.joints()[std::size_t(index)].max_velocity);
  }
  while (ros::WallTime::now() < deadline)
  {
    if (!armJoints().empty() && lookup(object_) && lookup(robot_.tcp_link))
    {
      ready_sim_ = ros::Time::now();
      ready_wall_ = ros::WallTime::now();
      return true;
    }
    ros::WallDuration(0.05).sleep();
  }
  return error = "no joint_states of " + robot_.name + " or no tf of '" + object_ + "' / " + robot_.tcp_link, false;
}

std::vector<double> WorkspaceClient::armJoints()
{
  std::lock_guard<std::mutex> lock(mutex_);
  return latest_;
}

std::optional<Eigen::Isometry3d> WorkspaceClient::lookup(const std::string& frame)
{
  try
  {
    return tf2::transformToEigen(tf_buffer_.lookupTransform("world", frame, ros::Time(0)));
  }
  catch (const tf2::TransformException&)
  {
    return std::nullopt;
  }
}

Eigen::Isometry3d WorkspaceClient::objectPose()
{
  return lookup(object_).value_or(Eigen::Isometry3d::Identity());
}

Eigen::Isometry3d WorkspaceClient::tcpPose()
{
  return lookup(robot_.tcp_link).value_or(Eigen::Isometry3d::Identity());
}

Eigen::Isometry3d WorkspaceClient::flangePose()
{
  return lookup(robot_.tool_link).value_or(Eigen::Isometry3d::Identity());
}

bool WorkspaceClient::execute(const vrrw_trajectory::JointTrajectory& trajectory, std::string& error)
{
  control_msgs::FollowJointTrajectoryGoal goal;
  goal.trajectory = toMsg(trajectory);
  arm_.sendGoal(goal);
  if (!arm_.waitForResult(ros::Duration(trajectory.duration() + 10.0)))
    return arm_.cancelGoal(), error = "no result within the trajectory's duration + 10 s", false;
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
  gripper_.sendGoal(goal);
  if (!gripper_.waitForResult(ros::Duration(10.0)))
    return gripper_.cancelGoal(), error = "gripper: no result within 10 s", false;
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
  // 50 ms: the closed-form UR solver takes microseconds (vrrw_kinematics' bench ik); the bound only keeps a
  // numeric search on another arm from holding a trial
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
  const auto q = vrrw_common::findValues(srv.response.solution.name, srv.response.solution.position, robot_.arm_joints);
  if (!q)
    return error = "compute_ik answered without every arm joint", std::nullopt;
  return q;
}

std::optional<vrrw_trajectory::JointTrajectory> WorkspaceClient::plan(const std::vector<double>& goal,
                                                                      std::string& error, double* plan_ms)
{
  vrrw_msgs::Plan srv;
  srv.request.goal_joints = jointState(robot_.arm_joints, goal);
  srv.request.time_limit = 2.0;  // s of OMPL's search: the demo's cell plans within 10 ms at p95 (bench plan)
  srv.request.seed = 1;  // the same plan for the same request: runs with one --seed repeat
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
  for (int i = 0; i < 100; ++i)
  {
    if ((objectPose().translation() - pose.translation()).norm() < 0.01)
      return true;
    ros::WallDuration(0.02).sleep();
  }
  return error = "tf never showed " + object_ + " where set_object_pose put it", false;
}

void WorkspaceClient::startRecording(const std::string& bag_file)
{
  demos_recording_ = false;
  if (!bag_file.empty())
  {
    std::remove(bag_file.c_str());  // the report's own bag of an earlier run (vrrw_demos never overwrites)
    // The one bag writer is vrrw_demos' recorder (./vrrw up and the demo's launch run it idle).
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
  recording_data_.recorder = "vrrw_demos recorder_node";
  recording_data_.arm.joint_names = robot_.arm_joints;
  record_start_ = ros::Time::now();
  recording_ = true;
}

Recording WorkspaceClient::stopRecording()
{
  std::uint64_t demos_messages = 0;
  if (demos_recording_)
  {
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
  recording_data_.seconds = (ros::Time::now() - record_start_).toSec();
  recording_data_.start_stamp = record_start_.toSec();
  return std::move(recording_data_);
}

void WorkspaceClient::annotate(const std::string& kind, const std::string& detail)
{
  if (demos_recording_)
  {
    vrrw_msgs::DemoAnnotate annotate;
    annotate.request.stamp = ros::Time::now();  // the bag's event at the instant the runner's clock says
    annotate.request.text = kind + " " + detail;
    links_.tryCall("/demos/annotate", annotate);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_)
    ++recording_data_.event_messages;
}

double WorkspaceClient::recordingTime() const
{
  return (ros::Time::now() - record_start_).toSec();
}

double WorkspaceClient::realTimeFactor() const
{
  return (ros::Time::now() - ready_sim_).toSec() / std::max(1e-9, (ros::WallTime::now() - ready_wall_).toSec());
}

void WorkspaceClient::onJointStates(const sensor_msgs::JointState::ConstPtr& msg)
{
  const auto q = vrrw_common::findValues(msg->name, msg->position, robot_.arm_joints);
  if (!q)
    return;  // the gripper's own message, or another robot's
  std::vector<double> qd = vrrw_common::findValues(msg->name, msg->velocity, robot_.arm_joints)
                               .value_or(std::vector<double>(q->size(), 0.0));
  std::lock_guard<std::mutex> lock(mutex_);
  latest_ = *q;
  if (!recording_)
    return;
  ++recording_data_.joint_state_messages;
  recording_data_.arm.points.push_back({ (msg->header.stamp - record_start_).toSec(), *q, std::move(qd), {} });
}

void WorkspaceClient::onContacts(const vrrw_physics::Contacts::ConstPtr& msg)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!recording_)
    return;
  ++recording_data_.contact_messages;
  for (const auto& c : msg->contacts)
    if (vrrw_skills::isArmCollision(c.body_a, c.body_b, robot_.name, obstacles_))
      recording_data_.arm_contacts.insert(c.body_a + "|" + c.body_b);
}

void WorkspaceClient::onTrackTimer(const ros::TimerEvent&)
{
  const auto tcp = lookup(robot_.tcp_link);
  const auto object = lookup(object_);
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_ && tcp && object)
    recording_data_.track.push_back({ (ros::Time::now() - record_start_).toSec(), tcp->translation(), *object });
}
}  // namespace vrrw_evaluation
