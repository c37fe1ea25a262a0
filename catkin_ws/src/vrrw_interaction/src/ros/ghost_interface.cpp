#include "ghost_interface.h"

#include <vrrw_msgs/GhostPreset.h>
#include <vrrw_msgs/GhostSupportSurface.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_interaction
{
namespace
{
/// A service answered by a request returning an Outcome.
template <class Service>
ros::ServiceServer outcomeService(ros::NodeHandle& nh, const std::string& name,
                                  std::function<Outcome(typename Service::Request&)> request)
{
  return nh.advertiseService<typename Service::Request, typename Service::Response>(
      name, [request](typename Service::Request& req, typename Service::Response& res) {
        const Outcome o = request(req);
        res.success = o.success, res.message = o.message;
        return true;
      });
}
}  // namespace

GhostInterface::GhostInterface(WorldView& view, const vrrw_scene::Robot& robot, const std::string& presets_file,
                               ros::CallbackQueue& execution_queue)
  : view_(view)
  , robot_(robot.name)
  , arm_(view.world(), robot)
  , ghost_(arm_, Presets::load(presets_file, robot.model, view.scene().source_file, robot.name, robot.arm_joints.size()),
           arm_.jointValues(view.liveState()))
  , gripper_(gripperRange(view.world().model(), robot))
  , arm_action_(robot.name)
  , gripper_action_("/" + robot.name + "/gripper_controller/gripper_cmd")
{
  ros::NodeHandle nh("/" + robot_ + "/ghost");
  // a preview in a lockstep client's step slice (0.25 s) goes out in one burst: up to 17 states, none dropped
  joint_states_ = nh.advertise<sensor_msgs::JointState>("joint_states", 100, true);
  advertise(nh, execution_queue);
  view_.onInstant([this](const ros::Time& stamp) { atInstant(stamp); });
}

void GhostInterface::advertise(ros::NodeHandle& nh, ros::CallbackQueue& execution_queue)
{
  services_.push_back(nh.advertiseService("set_joints", &GhostInterface::onSetJoints, this));
  services_.push_back(nh.advertiseService("set_pose", &GhostInterface::onSetPose, this));
  services_.push_back(nh.advertiseService("plan", &GhostInterface::onPlan, this));
  services_.push_back(outcomeService<vrrw_msgs::GhostPreset>(nh, "preset", [this](auto& req) { return preset(req.name); }));
  services_.push_back(outcomeService<vrrw_msgs::GhostSupportSurface>(
      nh, "set_support_surface", [this](auto& req) { return supportSurface(req.name); }));
  using Trigger = std_srvs::Trigger;
  services_.push_back(outcomeService<Trigger>(nh, "add_waypoint", [this](auto&) { return addWaypoint(); }));
  services_.push_back(outcomeService<Trigger>(nh, "clear_waypoints", [this](auto&) { return clearWaypoints(); }));
  services_.push_back(outcomeService<Trigger>(nh, "reset", [this](auto&) { return reset(); }));
  services_.push_back(outcomeService<Trigger>(nh, "gripper_open", [this](auto&) { return gripper(false); }));
  services_.push_back(outcomeService<Trigger>(nh, "gripper_close", [this](auto&) { return gripper(true); }));
  ros::NodeHandle execution(nh);
  execution.setCallbackQueue(&execution_queue);
  services_.push_back(execution.advertiseService("execute", &GhostInterface::onExecute, this));
}

Eigen::VectorXd GhostInterface::joints(const ros::Time& at)
{
  // while a plan previews, the ghost shows where the robot will be on it (on ROS time: the controller's pace)
  const std::optional<Eigen::VectorXd> previewed = preview_.at(at.toSec());
  return previewed ? *previewed : ghost_.joints();
}

void GhostInterface::ghostInto(Eigen::VectorXd& state, const ros::Time& at)
{
  state = arm_.withJointValues(state, joints(at));
}

void GhostInterface::atInstant(const ros::Time& stamp)
{
  const Eigen::VectorXd q = joints(stamp);
  const bool changed = sent_.size() != q.size() || (sent_ - q).cwiseAbs().maxCoeff() > 0.0;
  if (schedule_.due(stamp, changed))
    publish(q, stamp, stamp);
}

void GhostInterface::publish(const Eigen::VectorXd& q, const ros::Time& stamp, const ros::Time& at)
{
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  msg.name = arm_.jointNames();
  msg.position.assign(q.data(), q.data() + q.size());
  joint_states_.publish(msg);
  sent_ = q;
  schedule_.sent(at);
}

Outcome GhostInterface::drag(const Eigen::Isometry3d& target, const ros::Time& stamp, double max_jump)
{
  const Outcome outcome = ghost_.setPose(target, view_.liveState(), max_jump);
  if (outcome.success)
  {
    preview_.stop();
    publish(ghost_.joints(), stamp, view_.now());  // (the marker's stamp answers its pose; the schedule keeps ours)
  }
  return outcome;
}

Outcome GhostInterface::moved(const Outcome& outcome, const std::string& request)
{
  if (!outcome.success)
  {
    ROS_WARN_STREAM("/" << robot_ << "/ghost/" << request << ": " << outcome.message);
    return outcome;
  }
  preview_.stop();
  const ros::Time now = view_.now();
  publish(ghost_.joints(), now, now);
  if (on_published)
    on_published(now);
  if (on_moved)
    on_moved(tcp());
  return outcome;
}

bool GhostInterface::onSetJoints(vrrw_msgs::GhostSetJoints::Request& req, vrrw_msgs::GhostSetJoints::Response& res)
{
  view_.catchUp();
  std::lock_guard<std::mutex> lock(view_.mutex());
  const Outcome o = moved(ghost_.setJoints(req.name, req.position, view_.liveState()), "set_joints");
  res.success = o.success, res.message = o.message;
  return true;
}

bool GhostInterface::onSetPose(vrrw_msgs::GhostSetPose::Request& req, vrrw_msgs::GhostSetPose::Response& res)
{
  Outcome o;
  try
  {
    view_.catchUp();
    const Eigen::Isometry3d target = view_.poseInWorld(req.pose);  // (without the mutex: it may look up tf)
    std::lock_guard<std::mutex> lock(view_.mutex());
    o = moved(ghost_.setPose(target, view_.liveState(), std::numeric_limits<double>::infinity()), "set_pose");
  }
  catch (const std::exception& e)
  {
    o = { false, e.what() };
  }
  res.success = o.success, res.message = o.message;
  return true;
}

Outcome GhostInterface::preset(const std::string& name)
{
  view_.catchUp();
  std::lock_guard<std::mutex> lock(view_.mutex());
  const Outcome o = moved(ghost_.preset(name, view_.liveState()), "preset");
  if (o.success)
    view_.event(robot_, "preset", name);
  return o;
}

Outcome GhostInterface::addWaypoint()
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  view_.event(robot_, "waypoint", "added");
  return ghost_.addWaypoint();
}

Outcome GhostInterface::clearWaypoints()
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  return ghost_.clearWaypoints();
}

Outcome GhostInterface::reset()
{
  view_.catchUp();
  std::lock_guard<std::mutex> lock(view_.mutex());
  return moved(ghost_.reset(view_.liveState()), "reset");
}

Outcome GhostInterface::plan(double time_limit, trajectory_msgs::JointTrajectory* trajectory,
                             const vrrw_kinematics::SpeedScaling& scaling, vrrw_kinematics::TimeProfile profile)
{
  if (!std::isfinite(time_limit))
    return { false, "time_limit: not finite" };
  view_.catchUp();
  std::lock_guard<std::mutex> lock(view_.mutex());
  // planning holds the mutex (the arm's planner and the collision world are shared): up to time_limit
  const vrrw_kinematics::TrajectoryResult result = ghost_.plan(view_.liveState(), time_limit, scaling, profile);
  if (!result.success)
  {
    const int failed = result.failed_waypoint, waypoints = int(ghost_.waypoints().size());
    // -1: the start, or the request as a whole (a scaling factor, a plan too long)
    const std::string where = failed < 0 ? (result.code == vrrw_kinematics::ErrorCode::InvalidArgument ? "" : " at the start")
                                         : failed < waypoints ? " at the waypoint " + std::to_string(failed)
                                                              : " at the goal (the ghost)";
    const Outcome o{ false, "plan failed" + where + ": " + result.message };
    ROS_WARN_STREAM("/" << robot_ << "/ghost/plan: " << o.message);
    return o;
  }
  preview_.play(result.trajectory, view_.now().toSec());  // (sent at the live states' instants from here)
  if (trajectory)
    *trajectory = vrrw_trajectory::toMsg(result.trajectory);
  const std::string summary = std::to_string(result.trajectory.duration()) + " s through " +
                              std::to_string(ghost_.waypoints().size()) + " waypoints";
  view_.event(robot_, "plan", summary);
  return { true, "planned " + summary };
}

Outcome GhostInterface::execute(control_msgs::FollowJointTrajectoryResult* result)
{
  // the plan is taken (and forgotten: executed once) under the mutex; the motion is waited for without it
  trajectory_msgs::JointTrajectory plan;
  double duration = 0.0;
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    if (!ghost_.lastPlan())
      return { false, "execute: no plan (call plan first; a plan is executed once)" };
    plan = vrrw_trajectory::toMsg(*ghost_.lastPlan());
    duration = ghost_.lastPlan()->duration();
    ghost_.clearPlan();
    view_.event(robot_, "execute", std::to_string(duration) + " s");
  }
  return result ? arm_action_.run(plan, duration, *result) : arm_action_.send(plan);
}

Outcome GhostInterface::gripper(bool close)
{
  if (!gripper_)
    return { false, robot_ + " has no gripper" };
  if (!gripper_action_.isServerConnected())
    return { false, "/" + robot_ + "/gripper_controller/gripper_cmd is not running" };
  control_msgs::GripperCommandGoal goal;
  goal.command.position = close ? gripper_->closed : gripper_->open;
  view_.catchUp();     // lockstep: the state where the simulation waits,
  view_.awaitClock();  // and its instant on the ROS clock, which actionlib stamps the goal with
  std::lock_guard<std::mutex> lock(view_.mutex());  // (the simple client is not thread-safe; sending never waits)
  gripper_action_.sendGoal(goal);
  view_.event(robot_, close ? "gripper_close" : "gripper_open", "");
  return { true, close ? "closing" : "opening" };
}

Outcome GhostInterface::supportSurface(const std::string& name)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  if (!name.empty() && !view_.scene().object(name))
  {
    std::string objects;
    for (const vrrw_scene::Object& object : view_.scene().objects)
      objects += (objects.empty() ? "" : ", ") + object.name;
    return { false, "name: '" + name + "' is not an object of the scene (" + objects + ")" };
  }
  if (!name.empty() && view_.world().bodyIndex(name) < 0)
    return { false, "name: '" + name + "' has no collision geometry to set anything down on" };
  if (name.empty())
    ghost_.place_contact = nullptr;
  else  // (called by the ghost while the mutex is held)
    ghost_.place_contact = [this, name](bool allow) { view_.allowPlaceContact(robot_, name, allow); };
  view_.event(robot_, "support_surface", name);
  return { true, name.empty() ? "no support surface" : "held objects may be set down on " + name };
}

bool GhostInterface::onPlan(vrrw_msgs::GhostPlan::Request& req, vrrw_msgs::GhostPlan::Response& res)
{
  Outcome o;
  try
  {
    o = plan(req.time_limit, &res.trajectory,
             vrrw_kinematics::speedScaling(req.max_velocity_scaling_factor, req.max_acceleration_scaling_factor),
             vrrw_kinematics::timeProfile(req.time_profile));
  }
  catch (const std::exception& e)
  {
    o = { false, e.what() };
  }
  res.success = o.success, res.message = o.message;
  return true;
}

bool GhostInterface::onExecute(vrrw_msgs::GhostExecute::Request&, vrrw_msgs::GhostExecute::Response& res)
{
  control_msgs::FollowJointTrajectoryResult result;
  result.error_code = control_msgs::FollowJointTrajectoryResult::INVALID_GOAL;  // unless a goal was sent
  const Outcome o = execute(&result);
  res.success = o.success, res.message = o.message;
  res.error_code = result.error_code, res.error_string = result.error_string;
  return true;
}
}  // namespace vrrw_interaction
