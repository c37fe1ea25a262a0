#include "world_view.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_common/ros/clock.h>
#include <vrrw_kinematics/ik_solver.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_msgs/Event.h>
#include <std_srvs/Trigger.h>
#include <vrrw_physics/Step.h>

#include <chrono>
#include <thread>

namespace vrrw_interaction
{
namespace
{
/// Longest wait for the state where the simulation waits: its messages are one publish away (milliseconds).
constexpr double kCatchUpSeconds = 2.0;
/// Messages a subscription holds: at rtf max the states come in bursts (a lockstep client's slices, one after the
/// other) and this node may fall behind by many; none may be dropped (the ghost and the hands' markers are sent at
/// the states' instants). As physics_node's publishers: 20 s of states at 50 Hz.
constexpr int kBurst = 1000;
/// s: a state this much older than the newest is a simulation started again (/physics/reset), not a late one
constexpr double kClockWentBack = 1.0;
}  // namespace

WorldView::WorldView(ros::NodeHandle& nh, const vrrw_scene::Scene& scene, std::string mode)
  : scene_(scene)
  , mode_(std::move(mode))
  , world_(vrrw_kinematics::CollisionWorld::fromScene(scene_))
  , held_(world_, scene_)
  , listener_(tf_)
{
  world_.loadOrComputeAllowedCollisions(scene_.cache_dir);
  live_ = vrrw_kinematics::initialState(world_.model(), scene_);
  joint_states_ = nh.subscribe("/joint_states", kBurst, &WorldView::onJointStates, this);
  events_ = nh.advertise<vrrw_msgs::Event>("/operator/events", 100);
  if (mode_ == "physics")
    contacts_ = nh.subscribe("/physics/contacts", kBurst, &WorldView::onContacts, this);
  objects_timer_ = nh.createTimer(ros::Duration(0.1), [this](const ros::TimerEvent&) { refreshObjects(); });
  // answered once every state up to where a lockstep simulation waits is taken, and so what this node sends at
  // those instants is sent: a client that stops a recording there calls it first
  sync_ = nh.advertiseService<std_srvs::Trigger::Request, std_srvs::Trigger::Response>(
      "/interaction/sync", [this](std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
        catchUp();
        res.success = true;
        return true;
      });
}

void WorldView::onJointStates(const sensor_msgs::JointState& msg)
{
  std::vector<HeldEvent> events;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < msg.name.size() && i < msg.position.size(); ++i)
      if (const int v = world_.model().variableIndex(msg.name[i]); v >= 0 && std::isfinite(msg.position[i]))
        live_[v] = msg.position[i];
    const ros::Time& stamp = msg.header.stamp;  // (an unstamped state, say from rostopic pub, is no instant)
    if (!stamp.isZero() && (stamp > live_stamp_ || stamp + ros::Duration(kClockWentBack) < live_stamp_))
    {
      live_stamp_ = stamp;
      live_nsec_ = stamp.toNSec();
      if (mode_ == "physics")
      {
        recent_states_[stamp] = live_;
        while (recent_states_.size() > std::size_t(kBurst))
          recent_states_.erase(recent_states_.begin());
        for (auto c = early_contacts_.begin(); c != early_contacts_.end() && c->first <= stamp;)
        {
          for (HeldEvent& e : takeContacts(c->first, c->second, live_))
            events.push_back(std::move(e));
          c = early_contacts_.erase(c);
        }
      }
      for (const auto& at_instant : at_instant_)
        at_instant(live_stamp_);
    }
  }
  arrived_.notify_all();
  publish(events);
}

void WorldView::catchUp()
{
  vrrw_physics::Step where;  // duration 0: no step, the answer names the instant the simulation waits at
  {
    std::lock_guard<std::mutex> lock(step_mutex_);
    if (mode_ != "physics")
      return;
    if (!step_.isValid())  // (a persistent connection that broke is made anew)
      step_ = ros::NodeHandle().serviceClient<vrrw_physics::Step>("/physics/step", true);
    if (!step_.call(where) || !where.response.success)
      return;  // paced (the simulation runs), a step under way, or no physics node: the live state is all there is
  }
  const ros::Time at = where.response.time;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kCatchUpSeconds);
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!arrived_.wait_until(lock, deadline, [&] { return live_stamp_ >= at && contacts_stamp_ >= at; }))
    {
      ROS_WARN_STREAM_THROTTLE(5.0, "interaction: no joint state or contacts at the simulation's stop ("
                                        << at.toSec() << " s) within " << kCatchUpSeconds << " s: using the last ones");
      return;
    }
  }
  const std::string& root = world_.model().links()[0].name;  // (the model never changes: no lock)
  for (const vrrw_scene::Object& object : scene_.objects)
    while (!object.fixed && !tf_.canTransform(root, object.name, at) && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  refreshObjects(at);
}

void WorldView::refreshObjects(const ros::Time& at)
{
  const std::string& root = world_.model().links()[0].name;
  std::map<std::string, Eigen::Isometry3d> poses;  // looked up before taking the mutex
  for (const vrrw_scene::Object& object : scene_.objects)
    try
    {
      if (!object.fixed)
        poses[object.name] = tf2::transformToEigen(tf_.lookupTransform(root, object.name, at));
    }
    catch (const tf2::TransformException&)
    {
    }
  std::vector<HeldEvent> events;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [name, pose] : poses)
      if (const int b = world_.bodyIndex(name); b >= 0 && world_.bodies()[b].link < 0)
        world_.setObjectPose(name, pose);
    if (mode_ != "physics")  // physics decides by the contacts (onContacts)
      for (const vrrw_scene::Object& object : scene_.objects)
        if (!object.fixed)
          for (HeldEvent& e : held_.update(object.name, held_.heldByClosedGripper(object.name, live_), live_,
                                           ros::Time::now().toSec()))
            events.push_back(std::move(e));
    held_.releaseLifted(live_);
  }
  publish(events);
}

void WorldView::onContacts(const vrrw_physics::Contacts& msg)
{
  std::vector<BodyContact> contacts;
  for (const vrrw_physics::Contact& c : msg.contacts)
    contacts.push_back({ c.body_a, c.body_b, Eigen::Vector3d(c.position.x, c.position.y, c.position.z), c.normal_force });
  std::vector<HeldEvent> events;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time& stamp = msg.header.stamp;
    contacts_stamp_ = std::max(contacts_stamp_, stamp);
    if (const auto state = recent_states_.find(stamp); state != recent_states_.end())
      events = takeContacts(stamp, contacts, state->second);
    else if (stamp > live_stamp_ && early_contacts_.size() < std::size_t(kBurst))
      early_contacts_[stamp] = std::move(contacts);  // taken with its state (onJointStates)
    else
      events = takeContacts(stamp, contacts, live_);  // its state never came: the newest there is
  }
  arrived_.notify_all();
  publish(events);
}

std::vector<HeldEvent> WorldView::takeContacts(const ros::Time& stamp, const std::vector<BodyContact>& contacts,
                                               const Eigen::VectorXd& state)
{
  std::vector<HeldEvent> events;
  for (const vrrw_scene::Object& object : scene_.objects)
    if (!object.fixed)
      for (HeldEvent& e : held_.update(object.name, held_.squeezedBy(object.name, contacts, state), state, stamp.toSec()))
        events.push_back(std::move(e));
  return events;
}

void WorldView::publish(const std::vector<HeldEvent>& events)
{
  for (const HeldEvent& e : events)
    event(e.robot, e.kind, e.detail);
}

Eigen::Isometry3d WorldView::poseInWorld(const geometry_msgs::PoseStamped& pose, const std::string& field)
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
  const std::string& root = world_.model().links()[0].name;  // (the model never changes: no lock)
  const std::string& frame = pose.header.frame_id;
  if (frame.empty() || frame == root)
    return local;
  for (const vrrw_kinematics::LinkModel& link : world_.model().links())
    if (link.name == frame)  // a scene link at the live state
    {
      std::lock_guard<std::mutex> lock(mutex_);
      return world_.model().relativeTransform(live_, root, frame) * local;
    }
  try
  {
    // as tf has it now: a frame that is not there is refused at once (a stream in an unknown frame at 100 Hz
    // waiting 0.1 s a message kept the world's requests waiting: issue 21)
    return tf2::transformToEigen(tf_.lookupTransform(root, frame, ros::Time(0))) * local;
  }
  catch (const tf2::TransformException& e)
  {
    throw std::runtime_error(field + ".header.frame_id: unknown frame '" + frame + "' (" + e.what() + ")");
  }
}

void WorldView::allowPlaceContact(const std::string& robot, const std::string& surface, bool allow)
{
  held_.allowPlaceContact(robot, surface, allow);
}

void WorldView::awaitClock() const
{
  ros::Time instant;
  instant.fromNSec(live_nsec_);
  vrrw_common::awaitClock(instant);
}

void WorldView::event(const std::string& robot, const std::string& kind, const std::string& detail)
{
  awaitClock();
  vrrw_msgs::Event msg;
  msg.header.stamp = ros::Time::now();
  msg.source = "interaction";
  msg.robot = robot;
  msg.kind = kind;
  msg.detail = detail;
  events_.publish(msg);
}
}  // namespace vrrw_interaction
