#include "scene_context.h"

#include <tf2_eigen/tf2_eigen.h>

#include <vrrw_kinematics/ik_solver.h>
#include <vrrw_kinematics/scene_state.h>

namespace vrrw_kinematics
{
SceneContext::SceneContext(const vrrw_scene::Scene& scene, tf2_ros::Buffer& tf)
  : scene_(scene), world_(CollisionWorld::fromScene(scene)), tf_(tf)
{
  world_.loadOrComputeAllowedCollisions(scene.cache_dir);
  live_ = initialState(world_.model(), scene);
  robot_of_variable_.assign(world_.model().variableCount(), "");
  for (const vrrw_scene::Robot& robot : scene.robots)
    for (const auto& joint : robot.initial_positions)
      if (const int v = world_.model().variableIndex(joint.first); v >= 0)
        robot_of_variable_[static_cast<std::size_t>(v)] = robot.name;
}

void SceneContext::updateLive(const sensor_msgs::JointState& msg)
{
  const ros::WallTime now = ros::WallTime::now();
  for (std::size_t i = 0; i < msg.name.size() && i < msg.position.size(); ++i)
  {
    const int v = world_.model().variableIndex(msg.name[i]);
    if (v < 0 || !std::isfinite(msg.position[i]))
      continue;
    live_[v] = msg.position[i];
    if (const std::string& robot = robot_of_variable_[static_cast<std::size_t>(v)]; !robot.empty())
      last_state_[robot] = now;
  }
}

std::optional<double> SceneContext::stateAge(const std::string& robot) const
{
  const auto last = last_state_.find(robot);
  if (last == last_state_.end())
    return std::nullopt;
  return (ros::WallTime::now() - last->second).toSec();
}

void SceneContext::refreshObjects()
{
  const std::string& root = world_.model().links()[0].name;
  for (const vrrw_scene::Object& object : scene_.objects)
  {
    const int b = world_.bodyIndex(object.name);
    if (b < 0 || world_.bodies()[b].link >= 0 || !tf_.canTransform(root, object.name, ros::Time(0)))
      continue;
    try
    {
      world_.setObjectPose(object.name, tf2::transformToEigen(tf_.lookupTransform(root, object.name, ros::Time(0))));
    }
    catch (const tf2::TransformException&)
    {
    }
  }
}

void SceneContext::attach(const std::string& object, const std::string& link, const std::string& gripper_root)
{
  const RobotModel& model = world_.model();
  const int root = model.linkIndex(gripper_root);
  std::vector<std::string> touch;
  for (std::size_t l = 0; l < model.links().size(); ++l)
    if (model.isDescendant(static_cast<int>(l), root))
      touch.push_back(model.links()[l].name);
  world_.attachObject(object, link, live_, touch);
}

void SceneContext::detach(const std::string& object)
{
  world_.detachObject(object, live_);
}

Eigen::VectorXd SceneContext::overlay(const sensor_msgs::JointState& msg) const
{
  if (msg.name.size() != msg.position.size())
    throw KinematicsError(ErrorCode::InvalidArgument, "joint_state: " + std::to_string(msg.name.size()) +
                                                          " names but " + std::to_string(msg.position.size()) +
                                                          " positions");
  Eigen::VectorXd state = live_;
  for (std::size_t i = 0; i < msg.name.size(); ++i)
  {
    const int v = world_.model().variableIndex(msg.name[i]);
    if (v < 0)
    {
      world_.model().jointIndex(msg.name[i]);  // throws for a joint the scene does not have
      continue;                                // mimic and fixed joints follow the others
    }
    if (!std::isfinite(msg.position[i]))
      throw KinematicsError(ErrorCode::InvalidArgument, "joint_state: joint " + msg.name[i] + ": not finite");
    state[v] = msg.position[i];
  }
  return state;
}

Eigen::Isometry3d SceneContext::frameInWorld(const std::string& frame, const Eigen::VectorXd& state) const
{
  const std::string& root = world_.model().links()[0].name;
  if (frame.empty() || frame == root)
    return Eigen::Isometry3d::Identity();
  for (const LinkModel& link : world_.model().links())
    if (link.name == frame)
      return world_.model().relativeTransform(state, root, frame);
  try
  {
    return tf2::transformToEigen(tf_.lookupTransform(root, frame, ros::Time(0), ros::Duration(0.1)));
  }
  catch (const tf2::TransformException& e)
  {
    throw KinematicsError(ErrorCode::UnknownLink, "frame " + frame + ": unknown (" + e.what() + ")");
  }
}

Eigen::Isometry3d SceneContext::poseInWorld(const geometry_msgs::PoseStamped& pose, const Eigen::VectorXd& state) const
{
  const auto& p = pose.pose.position;
  const auto& o = pose.pose.orientation;
  const Eigen::Isometry3d local =
      poseFromQuaternion(Eigen::Vector3d(p.x, p.y, p.z), Eigen::Vector4d(o.x, o.y, o.z, o.w));
  return frameInWorld(pose.header.frame_id, state) * local;
}
}  // namespace vrrw_kinematics
