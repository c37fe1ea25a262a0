#include "world_view.h"

#include <algorithm>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_interaction/grab_target.h>
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
  for (const vrrw_scene::Robot& robot : scene.robots)
  {
    const int flange = world_.model().linkIndex(robot.tool_link);
    if (robot.gripper.empty() || flange < 0)
      continue;
    for (std::vector<int> below{ flange }; !below.empty();)
    {
      const vrrw_kinematics::LinkModel& link = world_.model().links()[below.back()];
      below.pop_back();
      gripper_links_[robot.name].push_back(link.name);
      below.insert(below.end(), link.child_links.begin(), link.child_links.end());
    }
  }
  if (mode_ == "physics")
    contacts_ = nh.subscribe("/physics/contacts", 10, &WorldView::onContacts, this);
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
  std::map<std::string, Eigen::Isometry3d> poses;
  for (const vrrw_scene::Object& object : scene_.objects)
    try
    {
      if (!object.fixed)
        poses[object.name] = tf2::transformToEigen(tf_.lookupTransform(root, object.name, ros::Time(0)));
    }
    catch (const tf2::TransformException&)
    {
    }
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [name, pose] : poses)
    if (const int b = world_.bodyIndex(name); b >= 0 && world_.bodies()[b].link < 0)
      world_.setObjectPose(name, pose);
  const double now = ros::WallTime::now().toSec();
  if (mode_ != "physics")  // physics decides by the contacts (onContacts)
    for (const vrrw_scene::Object& object : scene_.objects)
    {
      std::string holder;
      for (const vrrw_scene::Robot& robot : scene_.robots)
        if (!object.fixed && gripper_links_.count(robot.name) && fakeHolds(robot, object.name))
          holder = robot.name;
      if (!object.fixed)
        updateHeld(object.name, holder, now);
    }
  for (auto& [object, held] : held_)
    releaseSupports(object, held, false);
}

void WorldView::onContacts(const vrrw_physics::Contacts& msg)
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Eigen::Isometry3d> links;
  world_.model().linkTransforms(live_, links);
  const double now = ros::WallTime::now().toSec();
  for (const vrrw_scene::Object& object : scene_.objects)
  {
    if (object.fixed)
      continue;
    std::string holder;
    for (const auto& [robot, gripper] : gripper_links_)
    {
      // held: two gripper links press on it from opposite sides of the TCP (the two fingers squeeze it)
      const Eigen::Vector3d tcp = links[world_.model().linkIndex(scene_.robot(robot)->tcp_link)].translation();
      std::vector<Eigen::Vector3d> pads;
      for (const vrrw_physics::Contact& c : msg.contacts)
      {
        const std::string& other = c.body_a == object.name ? c.body_b : c.body_a;
        if ((c.body_a == object.name || c.body_b == object.name) && c.normal_force >= 0.5 &&
            std::find(gripper.begin(), gripper.end(), other) != gripper.end())
          pads.push_back(Eigen::Vector3d(c.position.x, c.position.y, c.position.z) - tcp);
      }
      for (std::size_t i = 0; i < pads.size(); ++i)
        for (std::size_t j = i + 1; j < pads.size(); ++j)
          if (pads[i].dot(pads[j]) < 0.0)
            holder = robot;
    }
    updateHeld(object.name, holder, now);
  }
}

bool WorldView::fakeHolds(const vrrw_scene::Robot& robot, const std::string& object) const
{
  const vrrw_kinematics::RobotModel& model = world_.model();
  const int j = robot.gripper_joints.empty() ? -1 : model.jointIndex(robot.gripper_joints[0]);
  const int v = j < 0 ? -1 : model.variableIndex(robot.gripper_joints[0]);
  if (v < 0)
    return false;
  const vrrw_kinematics::JointModel& joint = model.joints()[j];
  const bool prismatic = joint.type == vrrw_kinematics::JointModel::Type::Prismatic;  // Fetch: closed is lower
  const double closed = (live_[v] - joint.lower) / std::max(1e-9, joint.upper - joint.lower);
  if ((prismatic ? 1.0 - closed : closed) < 0.3)
    return false;
  const Eigen::Vector3d tcp = model.relativeTransform(live_, model.links()[0].name, robot.tcp_link).translation();
  return nearestBody(world_, live_, tcp, 0.01, [&](const vrrw_kinematics::CollisionBody& body) {
           return body.name == object;
         }).has_value();
}

void WorldView::updateHeld(const std::string& object, const std::string& robot, double now)
{
  const auto it = held_.find(object);
  if (!robot.empty() && it != held_.end())
  {
    if (it->second.robot == robot)
      it->second.last_seen = now;
    return;  // (held by another robot: it must let go first)
  }
  if (!robot.empty())
  {
    const std::string& tcp = scene_.robot(robot)->tcp_link;
    Held held{ robot, {}, {}, Eigen::Vector3d::Zero(), now };
    world_.attachObject(object, tcp, live_, gripper_links_[robot]);
    // a free object standing on the table is "always" touching it in the ACM: held, that pair is checked
    for (const vrrw_scene::Object& fixed : scene_.objects)
      if (fixed.fixed && world_.bodyIndex(fixed.name) >= 0 && world_.acm().allowed(object, fixed.name))
        held.restore.push_back(fixed.name), held.supports.push_back(fixed.name);
    // what it rests on may touch it until it is lifted: a plan starting at the grasp is not in collision
    for (int k = 0; k < 4; ++k)
    {
      const vrrw_kinematics::DistanceReport d = world_.distance(live_, object);
      const std::string& other = d.body_a == object ? d.body_b : d.body_a;
      const vrrw_scene::Object* support = scene_.object(other);
      if (d.distance > 0.005 || !support || !support->fixed)
        break;
      world_.setAllowed(object, other, true);
      held.supports.push_back(other);
    }
    std::vector<Eigen::Isometry3d> bodies;
    world_.bodyTransforms(live_, bodies);
    held.taken_at = bodies[world_.bodyIndex(object)].translation();
    std::string detail = object + " to " + tcp;
    for (const std::string& support : held.supports)
      detail += " (touching " + support + " until lifted 1 cm)";
    held_[object] = held;
    event(robot, "attach", detail);
    return;
  }
  if (it == held_.end() || now - it->second.last_seen < 0.3)
    return;
  releaseSupports(object, it->second, true);
  world_.detachObject(object, live_);
  for (const std::string& fixed : it->second.restore)
    world_.setAllowed(object, fixed, true);
  event(it->second.robot, "detach", object + " from " + scene_.robot(it->second.robot)->tcp_link);
  held_.erase(it);
}

void WorldView::releaseSupports(const std::string& object, Held& held, bool all)
{
  if (held.supports.empty())
    return;
  std::vector<Eigen::Isometry3d> bodies;
  world_.bodyTransforms(live_, bodies);
  if (!all && (bodies[world_.bodyIndex(object)].translation() - held.taken_at).norm() < 0.01)
    return;
  for (const std::string& support : held.supports)
    world_.setAllowed(object, support, false);
  held.supports.clear();
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
  // tf refuses a frame twice at one stamp (TF_REPEATED_DATA): under sim time, timer events that queued up
  // fire at one clock reading; the next tick sends the ghost as it is then.
  if (now <= last_ghost_stamp_)
    return;
  last_ghost_stamp_ = now;
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

void WorldView::allowPlaceContact(const std::string& robot, const std::string& surface, bool allow)
{
  if (!allow)
  {
    for (const auto& [object, other] : place_contacts_)
      world_.setAllowed(object, other, false);
    place_contacts_.clear();
    return;
  }
  for (const auto& [object, held] : held_)
    if (held.robot == robot && object != surface && !world_.acm().allowed(object, surface))
    {
      world_.setAllowed(object, surface, true);
      place_contacts_.emplace_back(object, surface);
    }
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
