#include "ghost_interface.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_interaction
{
namespace
{
/// \brief Linear interpolation of a trajectory at `t` s (the preview only needs to look right).
Eigen::VectorXd sample(const vrrw_trajectory::JointTrajectory& trajectory, double t)
{
  const auto& points = trajectory.points;
  std::size_t i = 1;
  while (i < points.size() && points[i].time < t)
    ++i;
  if (i >= points.size())
    return Eigen::Map<const Eigen::VectorXd>(points.back().positions.data(), points.back().positions.size());
  const auto& a = points[i - 1];
  const auto& b = points[i];
  const double s = b.time > a.time ? std::clamp((t - a.time) / (b.time - a.time), 0.0, 1.0) : 1.0;
  const Eigen::Map<const Eigen::VectorXd> qa(a.positions.data(), a.positions.size());
  const Eigen::Map<const Eigen::VectorXd> qb(b.positions.data(), b.positions.size());
  return qa + s * (qb - qa);
}
}  // namespace

GhostInterface::GhostInterface(WorldView& view, const vrrw_scene::Robot& robot, const std::string& presets_file)
  : view_(view)
  , robot_(robot.name)
  , arm_(view.world(), robot)
  , ghost_(arm_, Presets::load(presets_file, robot.model, view.scene().source_file, robot.name, robot.arm_joints.size()),
           arm_.jointValues(view.liveState()))
  , gripper_joints_(robot.gripper_joints)
  , arm_action_("/" + robot.name + "/arm_controller/follow_joint_trajectory", true)
  , gripper_action_("/" + robot.name + "/gripper_controller/gripper_cmd", true)
{
  if (!gripper_joints_.empty())
  {
    const auto& joint = view.world().model().joints()[view.world().model().jointIndex(gripper_joints_[0])];
    // Robotiq knuckles close with the angle; Fetch's prismatic fingers open with the gap.
    const bool prismatic = joint.type == vrrw_kinematics::JointModel::Type::Prismatic;
    gripper_open_ = prismatic ? joint.upper : joint.lower;
    gripper_closed_ = prismatic ? joint.lower : joint.upper;
  }
  ros::NodeHandle nh("/" + robot_ + "/ghost");
  joint_states_ = nh.advertise<sensor_msgs::JointState>("joint_states", 10, true);
  services_.push_back(nh.advertiseService("set_joints", &GhostInterface::onSetJoints, this));
  services_.push_back(nh.advertiseService("set_pose", &GhostInterface::onSetPose, this));
  services_.push_back(nh.advertiseService("plan", &GhostInterface::onPlan, this));
  services_.push_back(nh.advertiseService("execute", &GhostInterface::onExecute, this));
  services_.push_back(nh.advertiseService<vrrw_msgs::GhostPreset::Request, vrrw_msgs::GhostPreset::Response>(
      "preset", [this](auto& req, auto& res) {
        const Outcome o = preset(req.name);
        res.success = o.success, res.message = o.message;
        return true;
      }));
  services_.push_back(
      nh.advertiseService<vrrw_msgs::GhostSupportSurface::Request, vrrw_msgs::GhostSupportSurface::Response>(
          "set_support_surface", [this](auto& req, auto& res) {
            const Outcome o = supportSurface(req.name);
            res.success = o.success, res.message = o.message;
            return true;
          }));
  const auto trigger = [&](const std::string& name, std::function<Outcome()> request) {
    services_.push_back(nh.advertiseService<std_srvs::Trigger::Request, std_srvs::Trigger::Response>(
        name, [request](auto&, auto& res) {
          const Outcome o = request();
          res.success = o.success, res.message = o.message;
          return true;
        }));
  };
  trigger("add_waypoint", [this] { return addWaypoint(); });
  trigger("clear_waypoints", [this] { return clearWaypoints(); });
  trigger("reset", [this] { return reset(); });
  trigger("gripper_open", [this] { return gripper(false); });
  trigger("gripper_close", [this] { return gripper(true); });
  keepalive_ = nh.createTimer(ros::Duration(0.1), [this](const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(view_.mutex());
    publish(ros::Time::now());
  });
}

void GhostInterface::ghostInto(Eigen::VectorXd& state)
{
  const double t = (ros::WallTime::now() - preview_start_).toSec();
  const bool previewing = !preview_.points.empty() && t < preview_.duration() + 0.5;
  state = arm_.withJointValues(state, previewing ? sample(preview_, t) : ghost_.joints());
}

void GhostInterface::publish(const ros::Time& stamp)
{
  Eigen::VectorXd state = view_.liveState();
  ghostInto(state);
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  for (const std::string& joint : arm_.jointNames())
  {
    msg.name.push_back(joint);
    msg.position.push_back(state[view_.world().model().variableIndex(joint)]);
  }
  joint_states_.publish(msg);
}

Outcome GhostInterface::drag(const Eigen::Isometry3d& target, const ros::Time& stamp, double max_jump,
                             Eigen::Vector2d& residual)
{
  const Outcome outcome = ghost_.setPose(target, view_.liveState(), max_jump, &residual);
  if (outcome.success)
  {
    preview_.points.clear();
    publish(stamp);
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
  preview_.points.clear();
  publish(ros::Time::now());
  if (on_moved)
    on_moved(tcp());
  return outcome;
}

bool GhostInterface::onSetJoints(vrrw_msgs::GhostSetJoints::Request& req, vrrw_msgs::GhostSetJoints::Response& res)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  const Outcome o = moved(ghost_.setJoints(req.name, req.position, view_.liveState()), "set_joints");
  res.success = o.success, res.message = o.message;
  return true;
}

bool GhostInterface::onSetPose(vrrw_msgs::GhostSetPose::Request& req, vrrw_msgs::GhostSetPose::Response& res)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  Outcome o;
  try
  {
    o = ghost_.setPose(view_.poseInWorld(req.pose), view_.liveState(), std::numeric_limits<double>::infinity());
  }
  catch (const std::exception& e)
  {
    o = { false, e.what() };
  }
  o = moved(o, "set_pose");
  res.success = o.success, res.message = o.message;
  return true;
}

Outcome GhostInterface::preset(const std::string& name)
{
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
  std::lock_guard<std::mutex> lock(view_.mutex());
  return moved(ghost_.reset(view_.liveState()), "reset");
}

Outcome GhostInterface::plan(double time_limit, trajectory_msgs::JointTrajectory* trajectory,
                             const vrrw_kinematics::SpeedScaling& scaling, vrrw_kinematics::TimeProfile profile)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  if (!std::isfinite(time_limit))
    return { false, "time_limit: not finite" };
  const vrrw_kinematics::TrajectoryResult result = ghost_.plan(view_.liveState(), time_limit, scaling, profile);
  if (!result.success)
  {
    const std::string where = result.failed_waypoint >= 0 && result.failed_waypoint < int(ghost_.waypoints().size())
                                  ? "waypoint " + std::to_string(result.failed_waypoint)
                                  : (result.failed_waypoint < 0 ? "start" : "goal (the ghost)");
    const Outcome o{ false, "plan failed at the " + where + ": " + result.message };
    ROS_WARN_STREAM("/" << robot_ << "/ghost/plan: " << o.message);
    return o;
  }
  preview_ = result.trajectory;
  preview_start_ = ros::WallTime::now();
  if (trajectory)
    *trajectory = vrrw_trajectory::toMsg(result.trajectory);
  view_.event(robot_, "plan", std::to_string(ghost_.waypoints().size()) + " waypoints, " +
                                  std::to_string(result.trajectory.duration()) + " s");
  return { true, "planned " + std::to_string(result.trajectory.duration()) + " s through " +
                     std::to_string(ghost_.waypoints().size()) + " waypoints" };
}

Outcome GhostInterface::execute(control_msgs::FollowJointTrajectoryResult* result)
{
  control_msgs::FollowJointTrajectoryGoal goal;
  double duration = 0.0;
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    if (!ghost_.lastPlan())
      return { false, "execute: no plan (call plan first; a plan is executed once)" };
    goal.trajectory = vrrw_trajectory::toMsg(*ghost_.lastPlan());
    duration = ghost_.lastPlan()->duration();
    ghost_.clearPlan();
    view_.event(robot_, "execute", std::to_string(duration) + " s");
  }
  if (!arm_action_.waitForServer(ros::Duration(2.0)))
    return { false, "execute: /" + robot_ + "/arm_controller/follow_joint_trajectory is not running" };
  arm_action_.sendGoal(goal);
  if (!result)
    return { true, "sent" };
  if (!arm_action_.waitForResult(ros::Duration(duration + 30.0)))
    return { false, "execute: no result within " + std::to_string(duration + 30.0) + " s" };
  *result = *arm_action_.getResult();
  const bool ok = result->error_code == control_msgs::FollowJointTrajectoryResult::SUCCESSFUL;
  return { ok, ok ? "executed" : "execute: " + arm_action_.getState().toString() + ": " + result->error_string };
}

Outcome GhostInterface::gripper(bool close)
{
  if (gripper_joints_.empty())
    return { false, robot_ + " has no gripper" };
  if (!gripper_action_.waitForServer(ros::Duration(1.0)))
    return { false, "/" + robot_ + "/gripper_controller/gripper_cmd is not running" };
  control_msgs::GripperCommandGoal goal;
  goal.command.position = close ? gripper_closed_ : gripper_open_;
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
  else
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
