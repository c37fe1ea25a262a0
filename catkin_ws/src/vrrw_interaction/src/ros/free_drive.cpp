#include "free_drive.h"

#include <std_msgs/Bool.h>
#include <std_srvs/SetBool.h>
#include <tf2_eigen/tf2_eigen.h>
#include <trajectory_msgs/JointTrajectory.h>
#include <visualization_msgs/MarkerArray.h>

namespace vrrw_interaction
{
namespace
{
/// s of ROS time between the hands' markers (20 Hz: a viewer's rate)
constexpr double kMarkerPeriod = 0.05;
/// poses of a hand not yet shown (a script sends at most a step slice ahead; a tracker's own clock far ahead of
/// the simulation's is not kept beyond this)
constexpr std::size_t kMaxArriving = 1000;

std::string describe(const Eigen::Vector3d& p)
{
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "(%.3f, %.3f, %.3f)", p.x(), p.y(), p.z());
  return buffer;
}

/// A hand in rviz: darker when closed, faint when its tracker went silent.
visualization_msgs::Marker handMarker(const Hand& hand, bool closed, const std::string& frame, int id, double radius,
                                      double now)
{
  visualization_msgs::Marker sphere;
  sphere.header.frame_id = frame;
  sphere.header.stamp = ros::Time(now);  // the instant it shows
  sphere.ns = "hands", sphere.id = id;
  sphere.type = visualization_msgs::Marker::SPHERE;
  sphere.pose = tf2::toMsg(hand.pose());
  sphere.scale.x = sphere.scale.y = sphere.scale.z = 2 * radius;
  sphere.color.a = hand.stale(now) ? 0.2f : 0.8f;
  sphere.color.r = 0.95f, sphere.color.g = closed ? 0.3f : 0.75f, sphere.color.b = 0.5f;
  sphere.lifetime = ros::Duration(0.5);
  return sphere;
}
}  // namespace

FreeDrive::FreeDrive(WorldView& view, std::vector<GhostInterface*> arms, double grab_distance, double hand_radius,
                     const SpringGains& gains)
  : view_(view), hand_radius_(hand_radius), physics_(gains)
{
  ros::NodeHandle nh;
  rule_.max_distance = grab_distance;
  rule_.movable_objects = view_.mode() == "physics";  // objects move only in physics; the table and the bin never
  for (GhostInterface* arm : arms)
  {
    const std::string robot = arm->robot();
    arms_[robot] = arm;
    rule_.robots.insert(robot);
    active_pubs_[robot] = nh.advertise<std_msgs::Bool>("/" + robot + "/free_drive_active", 1, true);
    active_pubs_[robot].publish(std_msgs::Bool());
    commands_[robot] = nh.advertise<trajectory_msgs::JointTrajectory>("/" + robot + "/arm_controller/command", 1);
    services_.push_back(nh.advertiseService<std_srvs::SetBool::Request, std_srvs::SetBool::Response>(
        "/" + robot + "/free_drive", [this, robot](auto& req, auto& res) {
          const Outcome o = set(robot, req.data);
          res.success = o.success, res.message = o.message;
          return true;
        }));
  }
  hand_markers_ = nh.advertise<visualization_msgs::MarkerArray>("/operator/hands", 100);  // a burst of instants taken late
  discover_timer_ = nh.createWallTimer(ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { discoverHands(); });
  view_.onInstant([this](const ros::Time& now) { atInstant(now); });
  release_timer_ = nh.createWallTimer(ros::WallDuration(0.05), [this](const ros::WallTimerEvent&) { releaseStale(); });
}

Outcome FreeDrive::set(const std::string& robot, bool on)
{
  if (!arms_.count(robot))
    return { false, "robot: unknown robot '" + robot + "'" };
  // Drives first: rigid holds the pose the arm is in, then the controller may take over (no jump).
  if (view_.mode() == "physics")
    if (const Outcome mode = physics_.setMode(robot, on); !mode.success)
      return mode;
  std::lock_guard<std::mutex> lock(view_.mutex());
  std_msgs::Bool msg;
  msg.data = on;
  active_pubs_[robot].publish(msg);
  if (on != bool(active_.count(robot)))
    view_.event(robot, on ? "free_drive_on" : "free_drive_off", view_.mode());
  on ? (void)active_.insert(robot) : (void)active_.erase(robot);
  return { true, std::string("free-drive ") + (on ? "on" : "off") };
}

void FreeDrive::discoverHands()
{
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics))
    return;
  ros::NodeHandle nh;
  const std::string prefix = "/operator/", suffix = "/pose";
  for (const auto& topic : topics)
  {
    const std::string& name = topic.name;
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
  Eigen::Isometry3d pose;
  try
  {
    pose = view_.poseInWorld(msg, "/operator/" + tracker.hand.id() + "/pose");  // (before the mutex: tf)
  }
  catch (const std::exception& e)
  {
    ROS_WARN_STREAM_THROTTLE(1.0, e.what());
    return;
  }
  std::lock_guard<std::mutex> lock(view_.mutex());
  // the pose's own time when it is one of ours (a script stamps its hand ahead of the simulation): a lockstep run
  // marks and times out the hand at the same instants each time; else when it came
  const ros::Time now = view_.now(), stamp = msg.header.stamp;
  const bool own = !stamp.isZero() && std::abs((stamp - now).toSec()) < 1.0;
  tracker.hand.setPose(pose, (own ? stamp : now).toSec());
  if (tracker.arriving.size() < kMaxArriving)
    tracker.arriving[tracker.hand.poseTime()] = pose;  // (the newest of one time)
  if (tracker.hand.held())
    return follow(tracker, msg.header.stamp);
  if (view_.mode() != "physics")
    return;
  // the open hand pushes, once clear of what it let go (a sphere appearing inside a link would kick it)
  if (!tracker.pushes)
    tracker.pushes = clearOfMovingBodies(view_.world(), view_.scene(), view_.liveState(), pose.translation(),
                                         hand_radius_ + 0.01);
  physics_.hand(tracker.hand.id(), pose, tracker.pushes ? hand_radius_ : 0.0, msg.header.stamp);
}

void FreeDrive::onGrip(Tracker& tracker, const std_msgs::Float64& msg)
{
  if (const std::string error = gripError(msg.data); !error.empty())
  {
    ROS_WARN_STREAM_THROTTLE(1.0, "/operator/" << tracker.hand.id() << "/grip: data: " << error << " (ignored)");
    return;
  }
  std::optional<GrabTarget> taken, let_go;
  view_.catchUp();  // lockstep: grab from the state where the simulation waits, not one a message behind
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    const Hand::GripChange change = tracker.hand.setGrip(msg.data);
    if (change == Hand::GripChange::Close && !tracker.hand.held() && tracker.hand.hasPose())
      taken = grab(tracker);
    else if (change == Hand::GripChange::Open && tracker.hand.held())
      let_go = release(tracker);
  }
  const bool physics = view_.mode() == "physics";
  if (taken && (!physics || attachSpring(tracker, *taken)))
    grabbed(tracker, *taken);
  if (let_go && physics)
    physics_.release(tracker.spring, let_go->body);
  if (let_go)
    released(tracker, *let_go, "opened");
}

std::optional<GrabTarget> FreeDrive::grab(Tracker& tracker)
{
  const std::optional<GrabTarget> target =
      handGrab(view_.world(), view_.scene(), view_.liveState(), tracker.hand.pose().translation(), rule_);
  if (!target)
    return target;
  const vrrw_kinematics::RobotModel& model = view_.world().model();
  tracker.link_at_grab = target->object ? Eigen::Isometry3d::Identity()
                                        : model.relativeTransform(view_.liveState(), model.links()[0].name, target->body);
  if (!target->robot.empty())
    tracker.tcp_at_grab = tcpPose(arms_[target->robot]->arm(), view_.liveState());
  tracker.hand.hold(*target);
  tracker.pushes = false;
  physics_.hand(tracker.hand.id(), tracker.hand.pose(), 0.0, view_.now());
  return target;
}

void FreeDrive::grabbed(Tracker& tracker, const GrabTarget& target)
{
  view_.event(target.robot, "grab", "hand " + tracker.hand.id() + " grabbed " + target.body + " at " +
                                        describe(target.point_in_world));
}

bool FreeDrive::attachSpring(Tracker& tracker, const GrabTarget& target)
{
  // a link is held by position and orientation (the link's own at the grab: no pull), an object by position
  Eigen::Isometry3d at;
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    at = tracker.link_at_grab;
  }
  at.translation() = target.point_in_world;
  if (physics_.attach(tracker.spring, target.body, target.point_in_body, at, !target.object))
    return true;
  std::lock_guard<std::mutex> lock(view_.mutex());  // (physics warned why)
  if (tracker.hand.held() && tracker.hand.held()->body == target.body)
    release(tracker);
  return false;
}

GrabTarget FreeDrive::release(Tracker& tracker)
{
  const GrabTarget held = *tracker.hand.held();
  tracker.hand.release();
  return held;
}

void FreeDrive::released(Tracker& tracker, const GrabTarget& held, const std::string& why)
{
  view_.event(held.robot, "release", "hand " + tracker.hand.id() + " released " + held.body + " (" + why + ")");
}

void FreeDrive::follow(Tracker& tracker, const ros::Time& stamp)
{
  const GrabTarget& held = *tracker.hand.held();
  if (view_.mode() == "physics")
  {
    Eigen::Isometry3d target = tracker.hand.carried(tracker.link_at_grab);
    target.translation() = tracker.hand.heldPointTarget();
    physics_.moveTarget(tracker.spring, target, stamp);  // the hand's own time: deterministic when it runs ahead
    return;
  }
  // fake mode: the arm in free-drive follows the hand kinematically, at most 50 commands a second
  const ros::Time now = view_.now();
  if (held.robot.empty() || !active_.count(held.robot) || now - tracker.last_command < ros::Duration(0.02))
    return;
  vrrw_kinematics::Arm& arm = arms_[held.robot]->arm();
  const vrrw_kinematics::IkResult ik = armFollowingHand(arm, tracker.hand, tracker.tcp_at_grab, view_.liveState());
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
  tracker.last_command = now;
}

void FreeDrive::atInstant(const ros::Time& now)
{
  const double t = now.toSec();
  visualization_msgs::MarkerArray markers;
  for (auto& [id, tracker] : trackers_)
  {
    auto& arriving = tracker->arriving;
    for (auto p = arriving.begin(); p != arriving.end() && p->first < t; p = arriving.erase(p))
      tracker->shown.setPose(p->second, p->first);
    const Hand& shown = tracker->shown;
    if (tracker->hand.held() && shown.stale(t))
      stale_.emplace_back(tracker.get(), release(*tracker));
    if (tracker->pushes && shown.stale(t, 0.4))  // take the sphere away before physics has to
    {
      physics_.hand(id, shown.pose(), 0.0, now);
      tracker->pushes = false;
    }
    if (shown.hasPose())
      markers.markers.push_back(handMarker(shown, tracker->hand.closed(), view_.world().model().links()[0].name,
                                           int(markers.markers.size()), hand_radius_, t));
  }
  // (recordings keep /operator/*: no empty arrays)
  if (!markers.markers.empty() && (markers_at_.isZero() || (now - markers_at_).toSec() >= kMarkerPeriod - 1e-9))
  {
    hand_markers_.publish(markers);
    markers_at_ = now;
  }
}

void FreeDrive::releaseStale()
{
  std::vector<std::pair<Tracker*, GrabTarget>> stale;
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    stale.swap(stale_);
  }
  for (const auto& [tracker, held] : stale)
  {
    if (view_.mode() == "physics")
      physics_.release(tracker->spring, held.body);
    released(*tracker, held, "stale: no pose for 0.5 s");
  }
}
}  // namespace vrrw_interaction
