#include "ghost_marker.h"

#include <tf2_eigen/tf2_eigen.h>

namespace vrrw_interaction
{
namespace
{
visualization_msgs::InteractiveMarkerControl axisControl(const std::string& name, double x, double y, double z,
                                                         uint8_t mode)
{
  visualization_msgs::InteractiveMarkerControl control;
  control.name = name;
  control.orientation.w = 1.0, control.orientation.x = x, control.orientation.y = y, control.orientation.z = z;
  control.interaction_mode = mode;
  return control;
}
}  // namespace

GhostMarkers::GhostMarkers(WorldView& view, std::vector<GhostInterface*> ghosts, double rate, double max_jump,
                           const std::function<void(const std::string&, bool)>& free_drive)
  : view_(view), period_(1.0 / rate), max_jump_(max_jump), server_("interaction")
{
  for (GhostInterface* ghost : ghosts)
  {
    ghosts_[ghost->robot()] = ghost;
    buildMenu(*ghost, free_drive);
    Eigen::Isometry3d tcp;
    {
      std::lock_guard<std::mutex> lock(view_.mutex());
      tcp = ghost->tcp();
    }
    draw(ghost->robot(), tcp, "");
    ghost->on_moved = [this, robot = ghost->robot()](const Eigen::Isometry3d& pose) {
      // a service moved the ghost (the world's mutex is held: the server is left to the solver thread, as the
      // server calls onFeedback holding its own mutex); the marker follows, green
      {
        std::lock_guard<std::mutex> lock(pending_mutex_);
        moved_[robot] = pose;
      }
      wake_.notify_one();
    };
  }
  server_.applyChanges();
  solver_ = std::thread([this] { solveLoop(); });
}

GhostMarkers::~GhostMarkers()
{
  {
    std::lock_guard<std::mutex> lock(pending_mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  solver_.join();
}

void GhostMarkers::buildMenu(GhostInterface& ghost, const std::function<void(const std::string&, bool)>& free_drive)
{
  auto menu = std::make_unique<interactive_markers::MenuHandler>();
  using Feedback = visualization_msgs::InteractiveMarkerFeedbackConstPtr;
  const auto item = [&](const std::string& title, std::function<Outcome()> request,
                        interactive_markers::MenuHandler::EntryHandle parent = 0) {
    const auto callback = [request, title, robot = ghost.robot()](const Feedback&) {
      const Outcome o = request();
      ROS_INFO_STREAM(robot << " menu " << title << ": " << o.message);
    };
    parent ? menu->insert(parent, title, callback) : menu->insert(title, callback);
  };
  GhostInterface* g = &ghost;
  const auto presets = menu->insert("Preset");
  for (const std::string& name : ghost.presetNames())
    item(name, [g, name] { return g->preset(name); }, presets);
  item("Add waypoint", [g] { return g->addWaypoint(); });
  item("Clear waypoints", [g] { return g->clearWaypoints(); });
  item("Plan", [g] { return g->plan(0.0); });
  item("Execute", [g] { return g->execute(); });
  item("Reset ghost to robot", [g] { return g->reset(); });
  item("Gripper open", [g] { return g->gripper(false); });
  item("Gripper close", [g] { return g->gripper(true); });
  const std::string robot = ghost.robot();
  item("Free-drive on", [free_drive, robot] { return free_drive(robot, true), Outcome{ true, "free-drive on" }; });
  item("Free-drive off", [free_drive, robot] { return free_drive(robot, false), Outcome{ true, "free-drive off" }; });
  menus_[robot] = std::move(menu);
}

void GhostMarkers::draw(const std::string& robot, const Eigen::Isometry3d& pose, const std::string& status)
{
  visualization_msgs::InteractiveMarker marker;
  marker.header.frame_id = view_.world().model().links()[0].name;
  marker.name = robot;
  marker.description = status.empty() ? robot + " ghost" : robot + ": " + status;
  marker.scale = 0.2f;
  marker.pose = tf2::toMsg(pose);
  using C = visualization_msgs::InteractiveMarkerControl;
  const double s = std::sqrt(0.5);
  marker.controls = { axisControl("rotate_x", s, 0, 0, C::ROTATE_AXIS), axisControl("move_x", s, 0, 0, C::MOVE_AXIS),
                      axisControl("rotate_z", 0, s, 0, C::ROTATE_AXIS), axisControl("move_z", 0, s, 0, C::MOVE_AXIS),
                      axisControl("rotate_y", 0, 0, s, C::ROTATE_AXIS), axisControl("move_y", 0, 0, s, C::MOVE_AXIS) };
  for (std::size_t i = 0; i < 6; ++i)
    marker.controls[i].orientation.w = s;
  C handle;  // a sphere at the TCP: green when the ghost is there, red when the pose is refused; the menu
  handle.name = "menu";
  handle.interaction_mode = C::MENU;
  handle.always_visible = true;
  visualization_msgs::Marker sphere;
  sphere.type = visualization_msgs::Marker::SPHERE;
  sphere.scale.x = sphere.scale.y = sphere.scale.z = 0.04;
  sphere.color.a = 0.8f;
  (status.empty() ? sphere.color.g : sphere.color.r) = 0.9f;
  handle.markers.push_back(sphere);
  if (!status.empty())
  {
    visualization_msgs::Marker text = sphere;
    text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    text.text = status;
    text.scale.z = 0.04;
    text.pose.position.z = 0.08;
    text.color.a = 1.0f;
    handle.markers.push_back(text);
  }
  marker.controls.push_back(handle);
  server_.insert(marker, [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f) { onFeedback(f); });
  menus_.at(robot)->apply(server_, robot);
  status_[robot] = status;
}

void GhostMarkers::onFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback)
{
  if (feedback->event_type != visualization_msgs::InteractiveMarkerFeedback::POSE_UPDATE ||
      !ghosts_.count(feedback->marker_name))
    return;
  Eigen::Isometry3d pose;
  try
  {
    geometry_msgs::PoseStamped stamped;
    stamped.header = feedback->header;
    stamped.pose = feedback->pose;
    pose = view_.poseInWorld(stamped, "feedback");
  }
  catch (const std::exception& e)
  {
    ROS_WARN_STREAM_THROTTLE(1.0, "/interaction/feedback: marker " << feedback->marker_name << ": " << e.what());
    return;
  }
  {
    std::lock_guard<std::mutex> lock(pending_mutex_);
    pending_[feedback->marker_name] = Pending{ pose, feedback->header.stamp };  // latest wins
  }
  wake_.notify_one();
}

void GhostMarkers::solveLoop()
{
  std::map<std::string, ros::WallTime> last_draw;
  while (true)
  {
    std::map<std::string, Pending> work;
    std::map<std::string, Eigen::Isometry3d> moved;
    {
      std::unique_lock<std::mutex> lock(pending_mutex_);
      wake_.wait(lock, [this] { return stop_ || !pending_.empty() || !moved_.empty(); });
      if (stop_)
        return;
      work.swap(pending_);
      moved.swap(moved_);
    }
    // ghosts a service moved: their markers follow, green; then the newest dragged pose of each marker is solved
    const ros::WallTime start = ros::WallTime::now();
    bool changed = !moved.empty();
    for (const auto& [robot, pose] : moved)
    {
      std::lock_guard<std::mutex> lock(draw_mutex_);
      if (!status_[robot].empty())
        draw(robot, pose, "");
      server_.setPose(robot, tf2::toMsg(pose));
    }
    for (const auto& [robot, pending] : work)
    {
      Outcome outcome;
      {
        std::lock_guard<std::mutex> lock(view_.mutex());
        outcome = ghosts_[robot]->drag(pending.pose, pending.stamp, max_jump_);
      }
      const std::string status = outcome.success ? "" : outcome.message;
      std::lock_guard<std::mutex> lock(draw_mutex_);
      // a refused pose: the marker stays where the operator put it, red, saying why (redrawn at most 10 Hz)
      if (status != status_[robot] && (status.empty() != status_[robot].empty() || start - last_draw[robot] > ros::WallDuration(0.1)))
      {
        draw(robot, pending.pose, status);
        last_draw[robot] = start;
        changed = true;
      }
    }
    if (changed)
    {
      std::lock_guard<std::mutex> lock(draw_mutex_);
      server_.applyChanges();
    }
    // at most `rate` solves a second (wall clock: the operator's hand); poses arriving meanwhile coalesce
    const ros::WallDuration rest = ros::WallDuration(period_) - (ros::WallTime::now() - start);
    if (rest > ros::WallDuration(0))
      rest.sleep();
  }
}
}  // namespace vrrw_interaction
