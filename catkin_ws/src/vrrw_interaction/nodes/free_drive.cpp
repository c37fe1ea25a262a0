#include "free_drive.h"

#include <std_msgs/Bool.h>
#include <tf2_eigen/tf2_eigen.h>
#include <trajectory_msgs/JointTrajectory.h>
#include <vrrw_common/ros/persistent_service.h>
#include <visualization_msgs/MarkerArray.h>
#include <vrrw_physics/Hand.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetSpring.h>
#include <vrrw_physics/SpringTarget.h>

namespace vrrw_interaction
{
namespace
{
std::string describe(const Eigen::Vector3d& p)
{
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "(%.3f, %.3f, %.3f)", p.x(), p.y(), p.z());
  return buffer;
}

/// The physics node's services over persistent links (ros_comm#1976). A short wait for a missing service: the
/// callers hold the world lock. Never destroyed: its links must not be shut down after roscpp at exit.
vrrw_common::PersistentServices& physicsServices()
{
  static auto* services = new vrrw_common::PersistentServices({ 0.2, 5.0 });
  return *services;
}
}  // namespace

FreeDrive::FreeDrive(WorldView& view, std::vector<GhostInterface*> arms, double grab_distance, double hand_radius,
                     double angular_stiffness, double angular_damping)
  : view_(view)
  , grab_distance_(grab_distance)
  , hand_radius_(hand_radius)
  , angular_stiffness_(angular_stiffness)
  , angular_damping_(angular_damping)
{
  ros::NodeHandle nh;
  for (GhostInterface* arm : arms)
  {
    const std::string robot = arm->robot();
    arms_[robot] = arm;
    active_pubs_[robot] = nh.advertise<std_msgs::Bool>("/" + robot + "/free_drive_active", 1, true);
    active_pubs_[robot].publish(std_msgs::Bool());
    commands_[robot] = nh.advertise<trajectory_msgs::JointTrajectory>("/" + robot + "/arm_controller/command", 1);
    services_.push_back(nh.advertiseService<std_srvs::SetBool::Request, std_srvs::SetBool::Response>(
        "/" + robot + "/free_drive", [this, robot](auto& req, auto& res) {
          const std::string error = set(robot, req.data);
          res.success = error.empty();
          res.message = error.empty() ? std::string("free-drive ") + (req.data ? "on" : "off") : error;
          return true;
        }));
  }
  spring_target_ = nh.advertise<vrrw_physics::SpringTarget>("/physics/spring_target", 10);
  hand_pub_ = nh.advertise<vrrw_physics::Hand>("/physics/hand", 10);
  hand_markers_ = nh.advertise<visualization_msgs::MarkerArray>("/operator/hands", 1);
  discover_timer_ = nh.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { discoverHands(); });
  tick_timer_ = nh.createTimer(ros::Duration(0.05), [this](const ros::TimerEvent&) { tick(); });
  if (view_.mode() != "physics")
    return;
  mouse_ = std::make_unique<interactive_markers::InteractiveMarkerServer>("free_drive");
  for (const auto& [robot, arm] : arms_)
  {
    visualization_msgs::InteractiveMarker marker;
    marker.header.frame_id = view_.world().model().links()[0].name;  // kept on the live TCP by tick()
    marker.name = robot;
    marker.description = robot + " free-drive (drag to pull the TCP)";
    marker.scale = 0.15f;
    visualization_msgs::InteractiveMarkerControl control;
    control.interaction_mode = visualization_msgs::InteractiveMarkerControl::MOVE_3D;
    control.always_visible = true;
    visualization_msgs::Marker box;
    box.type = visualization_msgs::Marker::CUBE;
    box.scale.x = box.scale.y = box.scale.z = 0.03;
    box.color.b = 0.9f, box.color.a = 0.7f;
    control.markers.push_back(box);
    marker.controls.push_back(control);
    mouse_->insert(marker, [this](const auto& f) { onMouse(f); });
    mouse_at_[robot] = Eigen::Translation3d(Eigen::Vector3d::Constant(1e9)) * Eigen::Isometry3d::Identity();  // tick() places it
  }
  mouse_->applyChanges();
}

std::string FreeDrive::set(const std::string& robot, bool on)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  if (!arms_.count(robot))
    return "robot: unknown robot '" + robot + "'";
  if (view_.mode() == "physics")
  {
    // Drives first: rigid holds the pose the arm is in, then the controller may take over (no jump).
    vrrw_physics::SetMode srv;
    srv.request.robot = robot;
    srv.request.mode = on ? "compliant" : "rigid";
    if (!physicsServices().tryCall("/physics/set_mode", srv) || !srv.response.success)
      return "/physics/set_mode " + srv.request.mode + " failed: " +
             (srv.response.message.empty() ? "is the physics node running?" : srv.response.message);
  }
  std_msgs::Bool msg;
  msg.data = on;
  active_pubs_[robot].publish(msg);
  if (on != bool(active_.count(robot)))
    view_.event(robot, on ? "free_drive_on" : "free_drive_off", view_.mode());
  on ? (void)active_.insert(robot) : (void)active_.erase(robot);
  return "";
}

void FreeDrive::discoverHands()
{
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics))
    return;
  ros::NodeHandle nh;
  for (const auto& topic : topics)
  {
    const std::string& name = topic.name;
    const std::string prefix = "/operator/", suffix = "/pose";
    if (name.rfind(prefix, 0) != 0 || name.size() <= prefix.size() + suffix.size() ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string id = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    std::lock_guard<std::mutex> lock(view_.mutex());
    if (id.find('/') != std::string::npos || trackers_.count(id))
      continue;
    auto tracker = std::make_unique<Tracker>(id);
    Tracker* t = tracker.get();
    t->pose = nh.subscribe<geometry_msgs::PoseStamped>(name, 10, [this, t](const auto& msg) { onPose(*t, *msg); });
    t->grip = nh.subscribe<std_msgs::Float64>(prefix + id + "/grip", 10, [this, t](const auto& msg) { onGrip(*t, *msg); });
    trackers_[id] = std::move(tracker);
    ROS_INFO_STREAM("hand '" << id << "' on " << name);
  }
}

void FreeDrive::onPose(Tracker& tracker, const geometry_msgs::PoseStamped& msg)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  try
  {
    tracker.hand.setPose(view_.poseInWorld(msg, "/operator/" + tracker.hand.id() + "/pose"), ros::WallTime::now().toSec());
  }
  catch (const std::exception& e)
  {
    ROS_WARN_STREAM_THROTTLE(1.0, e.what());
    return;
  }
  if (tracker.hand.held())
    return follow(tracker);
  if (view_.mode() != "physics")
    return;
  // the open hand pushes, once clear of what it let go (a sphere appearing inside a link would kick it)
  if (!tracker.pushes)
    tracker.pushes = !nearestBody(view_.world(), view_.liveState(), tracker.hand.pose().translation(),
                                  hand_radius_ + 0.01, [this](const vrrw_kinematics::CollisionBody& body) {
                                    return !body.object || !view_.scene().object(body.name)->fixed;
                                  });
  publishHand(tracker, tracker.pushes ? hand_radius_ : 0.0);
}

void FreeDrive::onGrip(Tracker& tracker, const std_msgs::Float64& msg)
{
  std::lock_guard<std::mutex> lock(view_.mutex());
  if (const std::string error = gripError(msg.data); !error.empty())
  {
    ROS_WARN_STREAM_THROTTLE(1.0, "/operator/" << tracker.hand.id() << "/grip: data: " << error << " (ignored)");
    return;
  }
  const Hand::GripChange change = tracker.hand.setGrip(msg.data);
  if (change == Hand::GripChange::Close && !tracker.hand.held() && tracker.hand.hasPose())
    grab(tracker);
  else if (change == Hand::GripChange::Open && tracker.hand.held())
    release(tracker, "opened");
}

void FreeDrive::grab(Tracker& tracker)
{
  const bool physics = view_.mode() == "physics";
  const auto grabbable = [&](const vrrw_kinematics::CollisionBody& body) {
    if (body.object)  // objects move only in physics; the table and the bin never
      return physics && body.link < 0 && !view_.scene().object(body.name)->fixed;
    return arms_.count(body.robot) > 0;
  };
  const auto target = nearestBody(view_.world(), view_.liveState(), tracker.hand.pose().translation(),
                                  grab_distance_, grabbable);
  if (!target)
    return;
  // a link is held by position and orientation (the link's own now: no pull at the grab), an object by position
  const bool link = !target->object;
  tracker.link_at_grab = link ? view_.world().model().relativeTransform(
                                    view_.liveState(), view_.world().model().links()[0].name, target->body)
                              : Eigen::Isometry3d::Identity();
  Eigen::Isometry3d at = tracker.link_at_grab;
  at.translation() = target->point_in_world;
  if (physics && !spring("hand_" + tracker.hand.id(), target->body, target->point_in_body, at, link, false))
    return;
  tracker.hand.hold(*target);
  publishHand(tracker, 0.0);
  tracker.pushes = false;
  if (!target->robot.empty())
    tracker.tcp_at_grab = arms_[target->robot]->arm().basePose(view_.liveState()) *
                          arms_[target->robot]->arm().ikSolver().chain().fk(
                              arms_[target->robot]->arm().jointValues(view_.liveState()));
  view_.event(target->robot, "grab", "hand " + tracker.hand.id() + " grabbed " + target->body + " at " +
                                         describe(target->point_in_world));
}

void FreeDrive::release(Tracker& tracker, const std::string& why)
{
  const GrabTarget held = *tracker.hand.held();
  tracker.hand.release();
  if (view_.mode() == "physics")
    spring("hand_" + tracker.hand.id(), held.body, Eigen::Vector3d::Zero(), Eigen::Isometry3d::Identity(), false, true);
  view_.event(held.robot, "release", "hand " + tracker.hand.id() + " released " + held.body + " (" + why + ")");
}

void FreeDrive::follow(Tracker& tracker)
{
  const GrabTarget& held = *tracker.hand.held();
  if (view_.mode() == "physics")
  {
    vrrw_physics::SpringTarget msg;
    msg.id = "hand_" + tracker.hand.id();
    msg.target.position = tf2::toMsg(Eigen::Vector3d(tracker.hand.heldPointTarget()));
    msg.target.orientation = tf2::toMsg(Eigen::Quaterniond(tracker.hand.carried(tracker.link_at_grab).rotation()));
    spring_target_.publish(msg);
    return;
  }
  // fake mode: the arm in free-drive follows the hand kinematically, by IK of the TCP carried with the hand
  if (held.robot.empty() || !active_.count(held.robot) || ros::WallTime::now() - tracker.last_command < ros::WallDuration(0.02))
    return;
  vrrw_kinematics::Arm& arm = arms_[held.robot]->arm();
  vrrw_kinematics::IkOptions options;
  options.max_jump = 0.5;
  const auto ik = arm.solveCollisionFree(tracker.hand.carried(tracker.tcp_at_grab), arm.jointValues(view_.liveState()),
                                         view_.liveState(), options);
  if (!ik.success)
  {
    ROS_WARN_STREAM_THROTTLE(1.0, held.robot << " free-drive: hand " << tracker.hand.id() << ": " << ikRefusal(ik));
    return;
  }
  trajectory_msgs::JointTrajectory command;
  command.joint_names = arm.jointNames();
  command.points.resize(1);
  command.points[0].positions.assign(ik.q.data(), ik.q.data() + ik.q.size());
  command.points[0].time_from_start = ros::Duration(0.05);
  commands_[held.robot].publish(command);
  tracker.last_command = ros::WallTime::now();
}

void FreeDrive::publishHand(const Tracker& tracker, double radius)
{
  vrrw_physics::Hand msg;
  msg.id = tracker.hand.id();
  msg.pose = tf2::toMsg(tracker.hand.pose());
  msg.radius = radius;
  hand_pub_.publish(msg);
}

void FreeDrive::tick()
{
  std::map<std::string, Eigen::Isometry3d> tcps;
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    visualization_msgs::MarkerArray markers;
    const double now = ros::WallTime::now().toSec();
    for (auto& [id, tracker] : trackers_)
    {
      if (tracker->hand.held() && tracker->hand.stale(now))
        release(*tracker, "stale: no pose for 0.5 s");
      if (tracker->pushes && tracker->hand.stale(now, 0.4))  // take the sphere away before physics has to
      {
        publishHand(*tracker, 0.0);
        tracker->pushes = false;
      }
      if (!tracker->hand.hasPose())
        continue;
      visualization_msgs::Marker sphere;
      sphere.header.frame_id = view_.world().model().links()[0].name;
      sphere.ns = "hands", sphere.id = static_cast<int>(markers.markers.size());
      sphere.type = visualization_msgs::Marker::SPHERE;
      sphere.pose = tf2::toMsg(tracker->hand.pose());
      sphere.scale.x = sphere.scale.y = sphere.scale.z = 2 * hand_radius_;
      sphere.color.a = tracker->hand.stale(now) ? 0.2f : 0.8f;
      sphere.color.r = 0.95f, sphere.color.g = tracker->hand.closed() ? 0.3f : 0.75f, sphere.color.b = 0.5f;
      sphere.lifetime = ros::Duration(0.5);
      markers.markers.push_back(sphere);
    }
    if (!markers.markers.empty())  // (recordings keep /operator/*: no empty arrays at 20 Hz)
      hand_markers_.publish(markers);
    if (!mouse_)
      return;
    for (auto& [robot, arm] : arms_)
      if (!dragging_.count("mouse_" + robot))
        tcps[robot] = arm->arm().basePose(view_.liveState()) *
                      arm->arm().ikSolver().chain().fk(arm->arm().jointValues(view_.liveState()));
  }
  // The mouse markers sit on the live TCPs while nobody drags them. The server is called without the
  // world's mutex: it holds its own while calling onMouse, which takes the world's.
  bool moved = false;
  for (const auto& [robot, tcp] : tcps)
  {
    Eigen::Isometry3d& shown = mouse_at_[robot];
    if ((tcp.translation() - shown.translation()).norm() < 1e-3)
      continue;
    mouse_->setPose(robot, tf2::toMsg(tcp));
    shown = tcp, moved = true;
  }
  if (moved)
    mouse_->applyChanges();
}

void FreeDrive::onMouse(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f)
{
  using F = visualization_msgs::InteractiveMarkerFeedback;
  std::lock_guard<std::mutex> lock(view_.mutex());
  if (!arms_.count(f->marker_name))
    return;
  const std::string id = "mouse_" + f->marker_name;
  const std::string& tcp = arms_[f->marker_name]->arm().robot().tcp_link;
  geometry_msgs::PoseStamped pose;
  pose.header = f->header, pose.pose = f->pose;
  Eigen::Vector3d target;
  try
  {
    target = view_.poseInWorld(pose, "feedback").translation();
  }
  catch (const std::exception& e)
  {
    ROS_WARN_STREAM_THROTTLE(1.0, "/free_drive/feedback: " << e.what());
    return;
  }
  if (f->event_type == F::MOUSE_DOWN && !dragging_.count(id))
  {
    if (spring(id, tcp, Eigen::Vector3d::Zero(), Eigen::Translation3d(target) * Eigen::Isometry3d::Identity(), false, false))
      dragging_.insert(id), view_.event(f->marker_name, "grab", "mouse grabbed " + tcp);
  }
  else if (f->event_type == F::POSE_UPDATE && dragging_.count(id))
  {
    vrrw_physics::SpringTarget msg;
    msg.id = id;
    msg.target.position = tf2::toMsg(target);
    msg.target.orientation.w = 1.0;
    spring_target_.publish(msg);
  }
  else if (f->event_type == F::MOUSE_UP && dragging_.count(id))
  {
    spring(id, tcp, Eigen::Vector3d::Zero(), Eigen::Isometry3d::Identity(), false, true);
    dragging_.erase(id);
    view_.event(f->marker_name, "release", "mouse released " + tcp);
  }
}

bool FreeDrive::spring(const std::string& id, const std::string& body, const Eigen::Vector3d& point,
                       const Eigen::Isometry3d& target, bool angular, bool release)
{
  vrrw_physics::SetSpring srv;  // the recommended gains (physics' defaults): 5000 N/m, 100 N s/m, 200 N
  srv.request.id = id;
  srv.request.body = body;
  srv.request.point = tf2::toMsg(point);
  srv.request.target = tf2::toMsg(target);
  srv.request.stiffness = 5000.0, srv.request.damping = 100.0, srv.request.max_force = 200.0;
  if (angular)  // see the README: the wrist holds its orientation within 2 deg over the drag benchmark
    srv.request.angular_stiffness = angular_stiffness_, srv.request.angular_damping = angular_damping_;
  srv.request.release = release;
  if (physicsServices().tryCall("/physics/set_spring", srv) && srv.response.success)
    return true;
  ROS_WARN_STREAM("/physics/set_spring " << id << " on " << body << ": "
                                         << (srv.response.message.empty() ? "no physics node" : srv.response.message));
  return false;
}
}  // namespace vrrw_interaction
