#include "world_view.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_kinematics/ik_solver.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_msgs/Event.h>

namespace vrrw_interaction
{
WorldView::WorldView(ros::NodeHandle& nh, const vrrw_scene::Scene& scene, std::string mode)
  : scene_(scene)
  , world_(vrrw_kinematics::CollisionWorld::fromScene(scene))
  , mode_(std::move(mode))
  , listener_(tf_)
{
  world_.loadOrComputeAllowedCollisions(scene.cache_dir);
  live_ = vrrw_kinematics::initialState(world_.model(), scene);
  joint_states_ = nh.subscribe("/joint_states", 10, &WorldView::onJointStates, this);
  events_ = nh.advertise<vrrw_msgs::Event>("/operator/events", 100);
  objects_timer_ = nh.createTimer(ros::Duration(0.1), [this](const ros::TimerEvent&) { refreshObjects(); });
}

void WorldView::onJointStates(const sensor_msgs::JointState& msg)
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t i = 0; i < msg.name.size() && i < msg.position.size(); ++i)
    if (const int v = world_.model().variableIndex(msg.name[i]); v >= 0 && std::isfinite(msg.position[i]))
      live_[v] = msg.position[i];
}

void WorldView::refreshObjects()
{
  const std::string& root = world_.model().links()[0].name;
  for (const vrrw_scene::Object& object : scene_.objects)
  {
    if (object.fixed)
      continue;
    try
    {
      const Eigen::Isometry3d pose = tf2::transformToEigen(tf_.lookupTransform(root, object.name, ros::Time(0)));
      std::lock_guard<std::mutex> lock(mutex_);
      if (const int b = world_.bodyIndex(object.name); b >= 0 && world_.bodies()[b].link < 0)
        world_.setObjectPose(object.name, pose);
    }
    catch (const tf2::TransformException&)
    {
    }
  }
}

Eigen::Isometry3d WorldView::poseInWorld(const geometry_msgs::PoseStamped& pose, const std::string& field) const
{
  const auto& p = pose.pose.position;
  const auto& o = pose.pose.orientation;
  Eigen::Isometry3d local;
  try
  {
    local = vrrw_kinematics::poseFromQuaternion(Eigen::Vector3d(p.x, p.y, p.z), Eigen::Vector4d(o.x, o.y, o.z, o.w));
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error(field + ".pose: " + e.what());
  }
  const std::string& root = world_.model().links()[0].name;
  const std::string& frame = pose.header.frame_id;
  if (frame.empty() || frame == root)
    return local;
  for (const vrrw_kinematics::LinkModel& link : world_.model().links())
    if (link.name == frame)  // a scene link at the live state
      return world_.model().relativeTransform(live_, root, frame) * local;
  try
  {
    return tf2::transformToEigen(tf_.lookupTransform(root, frame, ros::Time(0), ros::Duration(0.1))) * local;
  }
  catch (const tf2::TransformException& e)
  {
    throw std::runtime_error(field + ".header.frame_id: unknown frame '" + frame + "' (" + e.what() + ")");
  }
}

void WorldView::publishGhostFrames(const Eigen::VectorXd& ghost_state)
{
  std::vector<Eigen::Isometry3d> links;
  world_.model().linkTransforms(ghost_state, links);
  const ros::Time now = ros::Time::now();
  const std::string& root = world_.model().links()[0].name;
  std::vector<geometry_msgs::TransformStamped> frames;
  frames.reserve(links.size());
  for (std::size_t l = 0; l < links.size(); ++l)
  {
    geometry_msgs::TransformStamped frame = tf2::eigenToTransform(links[l]);
    frame.header.stamp = now;
    frame.header.frame_id = root;
    frame.child_frame_id = "ghost/" + world_.model().links()[l].name;
    frames.push_back(frame);
  }
  broadcaster_.sendTransform(frames);
}

void WorldView::event(const std::string& robot, const std::string& kind, const std::string& detail)
{
  vrrw_msgs::Event msg;
  msg.header.stamp = ros::Time::now();
  msg.source = "interaction";
  msg.robot = robot;
  msg.kind = kind;
  msg.detail = detail;
  events_.publish(msg);
}
}  // namespace vrrw_interaction
