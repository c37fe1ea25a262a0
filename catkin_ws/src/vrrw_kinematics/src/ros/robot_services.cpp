#include "robot_services.h"

#include <algorithm>
#include <cmath>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_common/joint_mapping.h>
#include <vrrw_trajectory/msg_conversions.h>

namespace vrrw_kinematics
{
namespace
{
template <typename Response>
bool reply(Response& res, const KinematicsError& error)
{
  res.error_code = static_cast<int>(error.code());
  res.message = error.what();
  ROS_WARN_STREAM("planning_node: " << error.what());
  return true;
}

/// A pose goal left at its default (zero quaternion, no frame, origin): the request names no goal at all.
bool unset(const geometry_msgs::PoseStamped& pose)
{
  const auto& o = pose.pose.orientation;
  const auto& p = pose.pose.position;
  return pose.header.frame_id.empty() && o.x == 0.0 && o.y == 0.0 && o.z == 0.0 && o.w == 0.0 && p.x == 0.0 &&
         p.y == 0.0 && p.z == 0.0;
}

std::string withWarning(const std::string& message, const std::string& warning)
{
  return warning.empty() ? message : (message.empty() ? warning : message + "; " + warning);
}
}  // namespace

RobotServices::RobotServices(ros::NodeHandle& nh, const vrrw_scene::Robot& robot, SceneContext& context,
                             double stale_after)
  : arm_(context.world(), robot), context_(context), stale_after_(stale_after)
{
  const std::string ns = "/" + robot.name + "/";
  servers_.push_back(nh.advertiseService(ns + "compute_fk", &RobotServices::computeFk, this));
  servers_.push_back(nh.advertiseService(ns + "compute_ik", &RobotServices::computeIk, this));
  servers_.push_back(nh.advertiseService(ns + "check_state", &RobotServices::checkState, this));
  servers_.push_back(nh.advertiseService(ns + "check_path", &RobotServices::checkPath, this));
  servers_.push_back(nh.advertiseService(ns + "plan", &RobotServices::plan, this));
  servers_.push_back(nh.advertiseService(ns + "attach_object", &RobotServices::attachObject, this));
}

std::string RobotServices::linkOrTcp(const std::string& link) const
{
  return link.empty() ? arm_.robot().tcp_link : link;
}

std::string RobotServices::staleWarning(const sensor_msgs::JointState& given) const
{
  const auto& joints = arm_.jointNames();
  const bool all_given = vrrw_common::findJoints(given.name, joints).has_value();
  const std::optional<double> age = context_.stateAge(arm_.robot().name);
  if (all_given || !age || *age <= stale_after_)
    return "";
  char text[160];
  std::snprintf(text, sizeof(text), "warning: the last joint state of %s is %.1f s old (has its controller stopped?)",
                arm_.robot().name.c_str(), *age);
  ROS_WARN_STREAM_THROTTLE(5.0, "planning_node: " << text);
  return text;
}

bool RobotServices::computeFk(vrrw_msgs::ComputeFK::Request& req, vrrw_msgs::ComputeFK::Response& res)
{
  try
  {
    const Eigen::VectorXd state = context_.overlay(req.joint_state);
    const RobotModel& model = context_.world().model();
    const Eigen::Isometry3d in_world = model.relativeTransform(state, model.links()[0].name, linkOrTcp(req.link));
    res.pose.header.frame_id = req.frame_id.empty() ? model.links()[0].name : req.frame_id;
    res.pose.header.stamp = ros::Time::now();
    res.pose.pose = tf2::toMsg(context_.frameInWorld(req.frame_id, state).inverse() * in_world);
    res.error_code = 0;
    res.message = staleWarning(req.joint_state);
    return true;
  }
  catch (const KinematicsError& e)
  {
    return reply(res, e);
  }
}

bool RobotServices::computeIk(vrrw_msgs::ComputeIK::Request& req, vrrw_msgs::ComputeIK::Response& res)
{
  try
  {
    context_.refreshObjects();
    const Eigen::VectorXd state = context_.overlay(req.seed);
    const Eigen::Isometry3d target = context_.poseInWorld(req.pose, state);
    IkOptions options;
    options.mode = static_cast<IkOptions::Mode>(std::min<int>(req.mode, 2));
    options.orientation_tolerance = req.orientation_tolerance;
    options.timeout = req.timeout > 0.0 ? req.timeout : 0.005;
    const Eigen::VectorXd seed = arm_.jointValues(state);
    const IkResult result =
        req.avoid_collisions ?
            arm_.solveCollisionFree(target, seed, state, options, req.link) :
            arm_.ikSolver(req.link).solve(arm_.basePose(state).inverse() * target, seed, options);
    if (!result.success)
      throw KinematicsError(result.code, result.message);
    res.solution.header.stamp = ros::Time::now();
    res.solution.name = arm_.jointNames();
    res.solution.position.assign(result.q.data(), result.q.data() + result.q.size());
    res.error_code = 0;
    res.message = staleWarning(req.seed);
    return true;
  }
  catch (const KinematicsError& e)
  {
    return reply(res, e);
  }
}

bool RobotServices::checkState(vrrw_msgs::CheckState::Request& req, vrrw_msgs::CheckState::Response& res)
{
  try
  {
    context_.refreshObjects();
    const Eigen::VectorXd state = context_.overlay(req.joint_state);
    res.message = arm_.bounds().violation(arm_.jointValues(state));
    res.within_limits = res.message.empty();
    if (!res.within_limits)
      res.error_code = static_cast<int>(ErrorCode::OutsideLimits);
    const Contact contact = context_.world().check(state, arm_.robot().name);
    res.in_collision = contact.collision;
    res.link_a = contact.body_a;
    res.link_b = contact.body_b;
    if (contact.collision && res.within_limits)
    {
      res.error_code = static_cast<int>(ErrorCode::InCollision);
      res.message = "in collision: " + contact.body_a + " - " + contact.body_b;
    }
    res.min_distance = context_.world().distance(state, arm_.robot().name).distance;
    res.valid = res.within_limits && !res.in_collision;
    res.message = withWarning(res.message, staleWarning(req.joint_state));
    return true;
  }
  catch (const KinematicsError& e)
  {
    return reply(res, e);
  }
}

bool RobotServices::checkPath(vrrw_msgs::CheckPath::Request& req, vrrw_msgs::CheckPath::Response& res)
{
  try
  {
    const auto& points = req.path.points;
    if (points.size() > vrrw_msgs::CheckPath::Request::MAX_POINTS)
      throw KinematicsError(ErrorCode::InvalidArgument,
                            "check_path: path.points: " + std::to_string(points.size()) + " points; at most " +
                                std::to_string(vrrw_msgs::CheckPath::Request::MAX_POINTS) + " per call");
    // Every point is validated before any is checked: a bad one refuses the whole path, with its index.
    sensor_msgs::JointState point_state;
    point_state.name = req.path.joint_names;
    std::vector<Eigen::VectorXd> states;
    states.reserve(points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      point_state.position = points[k].positions;
      try
      {
        states.push_back(context_.overlay(point_state));
      }
      catch (const KinematicsError& e)
      {
        std::string reason = e.what();
        if (reason.rfind("joint_state: ", 0) == 0)
          reason.erase(0, 13);
        throw KinematicsError(e.code(), "check_path: path.points[" + std::to_string(k) + "]: " + reason);
      }
    }
    // Objects are read from tf once: the path is checked against the scene as it is at the call.
    context_.refreshObjects();
    for (const Eigen::VectorXd& state : states)
    {
      res.limit_violation.push_back(arm_.bounds().violation(arm_.jointValues(state)));
      const Contact contact = context_.world().check(state, arm_.robot().name);
      res.link_a.push_back(contact.collision ? contact.body_a : "");
      res.link_b.push_back(contact.collision ? contact.body_b : "");
    }
    res.error_code = 0;
    res.message = staleWarning(point_state);
    return true;
  }
  catch (const KinematicsError& e)
  {
    res.limit_violation.clear();
    res.link_a.clear();
    res.link_b.clear();
    return reply(res, e);
  }
}

Eigen::VectorXd RobotServices::goalJoints(const sensor_msgs::JointState& goal, const Eigen::VectorXd& start) const
{
  if (goal.name.size() != goal.position.size())
    throw KinematicsError(ErrorCode::InvalidArgument, "goal_joints: " + std::to_string(goal.name.size()) +
                                                          " names but " + std::to_string(goal.position.size()) +
                                                          " positions");
  std::vector<std::size_t> at;
  try
  {
    at = vrrw_common::robotIndices(goal.name, arm_.jointNames());
  }
  catch (const vrrw_common::JointMappingError& e)
  {
    throw KinematicsError(ErrorCode::InvalidArgument,
                          "goal_joints: joint " + e.joint() + ": " +
                              (e.reason() == "named twice" ? e.reason() : "not in the arm of " + arm_.robot().name));
  }
  Eigen::VectorXd values = start;
  for (std::size_t i = 0; i < at.size(); ++i)
    values[static_cast<Eigen::Index>(at[i])] = goal.position[i];
  return values;
}

PlanRequest RobotServices::planRequest(const vrrw_msgs::Plan::Request& req, const Eigen::VectorXd& state) const
{
  PlanRequest request;
  request.start = arm_.jointValues(state);
  if (!req.goal_joints.name.empty() || !req.goal_joints.position.empty())
    request.goal_joints = goalJoints(req.goal_joints, request.start);
  else if (unset(req.goal_pose))
    throw KinematicsError(ErrorCode::InvalidArgument, "no goal: give goal_joints (names and positions) or goal_pose");
  else
    request.goal_pose = context_.poseInWorld(req.goal_pose, state);
  if (!std::isfinite(req.time_limit) || req.time_limit < 0.0)
    throw KinematicsError(ErrorCode::InvalidArgument,
                          "time_limit: " + std::to_string(req.time_limit) + " s: must be positive (0: 1 s)");
  request.planner = req.planner.empty() ? "RRTConnect" : req.planner;
  request.time_limit = req.time_limit > 0.0 ? req.time_limit : 1.0;
  request.seed = req.seed != 0 ? req.seed : static_cast<std::uint64_t>(ros::WallTime::now().toNSec());
  return request;
}

bool RobotServices::plan(vrrw_msgs::Plan::Request& req, vrrw_msgs::Plan::Response& res)
{
  try
  {
    context_.refreshObjects();
    const Eigen::VectorXd state = context_.overlay(req.start);
    TrajectoryRequest request;
    request.plan = planRequest(req, state);
    request.scaling = speedScaling(req.max_velocity_scaling_factor, req.max_acceleration_scaling_factor);
    request.profile = timeProfile(req.time_profile);
    const TrajectoryResult result = arm_.planTrajectory(request, state, req.link);
    res.planning_time = result.planning_time;
    if (!result.success)
      throw KinematicsError(result.code, result.message);
    res.path_length = result.path_length;
    res.trajectory = vrrw_trajectory::toMsg(result.trajectory);
    res.error_code = 0;
    res.message = withWarning("planned in " + std::to_string(result.planning_time * 1e3) + " ms, " +
                                  std::to_string(result.trajectory.duration()) + " s of motion",
                              staleWarning(req.start));
    return true;
  }
  catch (const KinematicsError& e)
  {
    return reply(res, e);
  }
}

bool RobotServices::attachObject(vrrw_msgs::AttachObject::Request& req, vrrw_msgs::AttachObject::Response& res)
{
  try
  {
    const int b = context_.world().bodyIndex(req.object);
    if (b < 0 || !context_.world().bodies()[b].object)
      throw KinematicsError(ErrorCode::InvalidArgument, "object " + req.object + ": not a scene object");
    if (req.attach)
    {
      context_.refreshObjects();
      context_.attach(req.object, linkOrTcp(req.link), arm_.robot().tool_link);
      res.message = req.object + " attached to " + linkOrTcp(req.link);
    }
    else
    {
      context_.detach(req.object);
      res.message = req.object + " detached";
    }
    res.error_code = 0;
    return true;
  }
  catch (const KinematicsError& e)
  {
    return reply(res, e);
  }
}
}  // namespace vrrw_kinematics
