#include "robot_services.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <random>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_trajectory/msg_conversions.h>

#include "vrrw_kinematics/motion_planner.h"
#include "vrrw_kinematics/scene_state.h"
#include "vrrw_kinematics/state_checker.h"

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
}  // namespace

RobotServices::RobotServices(ros::NodeHandle& nh, const vrrw_scene::Robot& robot, SceneContext& context)
  : robot_(robot), context_(context)
{
  const RobotModel& model = context.world().model();
  if (robot.arm_joints.empty())
    throw KinematicsError(ErrorCode::InvalidArgument, "robot " + robot.name + ": no arm joints");
  arm_base_ = model.links()[model.joints()[model.jointIndex(robot.arm_joints.front())].parent_link].name;
  TimingOptions timing;
  for (const std::string& joint : robot.arm_joints)
  {
    arm_variables_.push_back(model.variableIndex(joint));
    timing.max_velocity.push_back(model.joints()[model.jointIndex(joint)].max_velocity);
  }
  timing.max_acceleration = armAccelerationLimits(robot);
  timing_ = std::make_unique<TimeParameterization>(timing);
  timing.max_deviation = 0.0;
  timing_exact_ = std::make_unique<TimeParameterization>(timing);
  solverFor(robot.tcp_link);
  const std::string ns = "/" + robot.name + "/";
  servers_.push_back(nh.advertiseService(ns + "compute_fk", &RobotServices::computeFk, this));
  servers_.push_back(nh.advertiseService(ns + "compute_ik", &RobotServices::computeIk, this));
  servers_.push_back(nh.advertiseService(ns + "check_state", &RobotServices::checkState, this));
  servers_.push_back(nh.advertiseService(ns + "plan", &RobotServices::plan, this));
  servers_.push_back(nh.advertiseService(ns + "attach_object", &RobotServices::attachObject, this));
}

std::string RobotServices::linkOrTcp(const std::string& link) const
{
  return link.empty() ? robot_.tcp_link : link;
}

const IkSolver& RobotServices::solverFor(const std::string& link)
{
  auto it = solvers_.find(link);
  if (it == solvers_.end())
  {
    const KinematicChain chain(context_.world().model(), arm_base_, link);
    if (chain.jointNames() != robot_.arm_joints)
      throw KinematicsError(ErrorCode::NotSerialChain, "chain " + arm_base_ + " -> " + link +
                                                           ": its movable joints are not the arm of " + robot_.name);
    it = solvers_.emplace(link, std::make_unique<IkSolver>(chain)).first;
  }
  return *it->second;
}

Eigen::VectorXd RobotServices::armValues(const Eigen::VectorXd& state) const
{
  Eigen::VectorXd arm(static_cast<Eigen::Index>(arm_variables_.size()));
  for (std::size_t i = 0; i < arm_variables_.size(); ++i)
    arm[static_cast<Eigen::Index>(i)] = state[arm_variables_[i]];
  return arm;
}

void RobotServices::setArm(Eigen::VectorXd& state, const Eigen::VectorXd& arm) const
{
  for (std::size_t i = 0; i < arm_variables_.size(); ++i)
    state[arm_variables_[i]] = arm[static_cast<Eigen::Index>(i)];
}

bool RobotServices::computeFk(vrrw_msgs::ComputeFK::Request& req, vrrw_msgs::ComputeFK::Response& res)
{
  try
  {
    const Eigen::VectorXd state = context_.overlay(req.joint_state);
    const std::string link = linkOrTcp(req.link);
    const RobotModel& model = context_.world().model();
    const Eigen::Isometry3d in_world = model.relativeTransform(state, model.links()[0].name, link);
    const Eigen::Isometry3d pose = context_.frameInWorld(req.frame_id, state).inverse() * in_world;
    res.pose.header.frame_id = req.frame_id.empty() ? model.links()[0].name : req.frame_id;
    res.pose.header.stamp = ros::Time::now();
    res.pose.pose = tf2::toMsg(pose);
    res.error_code = 0;
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
    Eigen::VectorXd state = context_.overlay(req.seed);
    const IkSolver& solver = solverFor(linkOrTcp(req.link));
    const Eigen::Isometry3d target =
        context_.frameInWorld(arm_base_, state).inverse() * context_.poseInWorld(req.pose, state);
    IkOptions options;
    options.mode = static_cast<IkOptions::Mode>(std::min<int>(req.mode, 2));
    options.orientation_tolerance = req.orientation_tolerance;
    options.timeout = req.timeout > 0.0 ? req.timeout : 0.005;
    const Eigen::VectorXd seed = armValues(state);
    std::vector<Eigen::VectorXd> candidates = solver.solveAll(target, seed);
    std::sort(candidates.begin(), candidates.end(), [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
      return (a - seed).squaredNorm() < (b - seed).squaredNorm();
    });
    if (candidates.empty() || options.mode != IkOptions::Mode::Full)
    {
      candidates.clear();
      const IkResult result = solver.solve(target, seed, options);
      if (!result.success)
        throw KinematicsError(result.code, result.message);
      candidates.push_back(result.q);
    }
    std::optional<StateChecker> checker;
    if (req.avoid_collisions)
      checker.emplace(context_.world(), robot_.arm_joints, state);
    std::mt19937_64 rng(1);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.timeout);
    for (std::size_t i = 0;; ++i)
    {
      if (i < candidates.size())
      {
        if (!checker || checker->valid(candidates[i]))
        {
          setArm(state, candidates[i]);
          break;
        }
        continue;
      }
      if (!checker || solver.hasAnalytic() || std::chrono::steady_clock::now() > deadline)
        throw KinematicsError(ErrorCode::InCollision, "compute_ik: every solution found is in collision");
      options.seed = rng();
      const IkResult retry = solver.solve(target, solver.chain().randomState(rng), options);
      if (retry.success)
        candidates.push_back(retry.q);
      else
        candidates.push_back(candidates.back());
    }
    res.solution.header.stamp = ros::Time::now();
    res.solution.name = robot_.arm_joints;
    for (const int v : arm_variables_)
      res.solution.position.push_back(state[v]);
    res.error_code = 0;
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
    const RobotModel& model = context_.world().model();
    res.within_limits = true;
    for (const int v : arm_variables_)
    {
      const JointModel& joint = model.joints()[model.variableJoints()[v]];
      if (joint.type != JointModel::Type::Continuous && (state[v] < joint.lower - 1e-9 || state[v] > joint.upper + 1e-9))
      {
        res.within_limits = false;
        res.error_code = static_cast<int>(ErrorCode::OutsideLimits);
        res.message = "joint " + joint.name + " = " + std::to_string(state[v]) + " outside [" +
                      std::to_string(joint.lower) + ", " + std::to_string(joint.upper) + "]";
        break;
      }
    }
    const Contact contact = context_.world().check(state, robot_.name);
    res.in_collision = contact.collision;
    res.link_a = contact.body_a;
    res.link_b = contact.body_b;
    if (contact.collision && res.within_limits)
    {
      res.error_code = static_cast<int>(ErrorCode::InCollision);
      res.message = "in collision: " + contact.body_a + " - " + contact.body_b;
    }
    res.min_distance = context_.world().distance(state, robot_.name).distance;
    res.valid = res.within_limits && !res.in_collision;
    return true;
  }
  catch (const KinematicsError& e)
  {
    return reply(res, e);
  }
}

bool RobotServices::plan(vrrw_msgs::Plan::Request& req, vrrw_msgs::Plan::Response& res)
{
  try
  {
    context_.refreshObjects();
    const Eigen::VectorXd state = context_.overlay(req.start);
    MotionPlanner planner(context_.world(), robot_.arm_joints, linkOrTcp(req.link), state);
    PlanRequest request;
    request.start = armValues(state);
    if (!req.goal_joints.position.empty())
    {
      if (req.goal_joints.name.size() != req.goal_joints.position.size())
        throw KinematicsError(ErrorCode::InvalidArgument, "goal_joints: names and positions differ in count");
      Eigen::VectorXd goal = request.start;
      for (std::size_t i = 0; i < req.goal_joints.name.size(); ++i)
      {
        const auto it = std::find(robot_.arm_joints.begin(), robot_.arm_joints.end(), req.goal_joints.name[i]);
        if (it == robot_.arm_joints.end())
          throw KinematicsError(ErrorCode::InvalidArgument,
                                "goal_joints: joint " + req.goal_joints.name[i] + ": not in the arm of " + robot_.name);
        goal[it - robot_.arm_joints.begin()] = req.goal_joints.position[i];
      }
      request.goal_joints = goal;
    }
    else
    {
      request.goal_pose = context_.poseInWorld(req.goal_pose, state);
    }
    request.planner = req.planner.empty() ? "RRTConnect" : req.planner;
    request.time_limit = req.time_limit > 0.0 ? req.time_limit : 1.0;
    request.seed = req.seed != 0 ? req.seed : static_cast<std::uint64_t>(ros::WallTime::now().toNSec());
    const PlanResult result = planner.plan(request);
    res.planning_time = result.planning_time;
    if (!result.success)
      throw KinematicsError(result.code, result.message);
    res.path_length = result.path_length;
    vrrw_trajectory::JointTrajectory trajectory = timing_->compute(result.path, robot_.arm_joints);
    if (!planner.trajectoryValid(trajectory))
      trajectory = timing_exact_->compute(result.path, robot_.arm_joints);
    res.trajectory = vrrw_trajectory::toMsg(trajectory);
    res.error_code = 0;
    res.message = "planned in " + std::to_string(result.planning_time * 1e3) + " ms, " +
                  std::to_string(trajectory.duration()) + " s of motion";
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
      context_.attach(req.object, linkOrTcp(req.link), robot_.tool_link);
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
