#include "mouse_drag.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_interaction/hand.h>

namespace vrrw_interaction
{
MouseDrag::MouseDrag(WorldView& view, std::vector<GhostInterface*> arms, const SpringGains& gains)
  : view_(view), physics_(gains), server_("free_drive")
{
  for (GhostInterface* arm : arms)
  {
    const std::string robot = arm->robot();
    arms_[robot] = arm;
    visualization_msgs::InteractiveMarker marker;
    marker.header.frame_id = view_.world().model().links()[0].name;
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
    server_.insert(marker, [this](const auto& f) { onFeedback(f); });
    shown_at_[robot] = Eigen::Translation3d(Eigen::Vector3d::Constant(1e9)) * Eigen::Isometry3d::Identity();
  }
  server_.applyChanges();
  timer_ = ros::NodeHandle().createWallTimer(ros::WallDuration(0.05), [this](const auto&) { placeMarkers(); });
}

void MouseDrag::placeMarkers()
{
  // the TCPs of the boxes nobody holds, then (without the world's mutex) the boxes moved where they changed
  std::set<std::string> dragging;
  {
    std::lock_guard<std::mutex> lock(drag_mutex_);
    dragging = dragging_;
  }
  std::map<std::string, Eigen::Isometry3d> tcps;
  {
    std::lock_guard<std::mutex> lock(view_.mutex());
    for (auto& [robot, arm] : arms_)
      if (!dragging.count(robot))
        tcps[robot] = tcpPose(arm->arm(), view_.liveState());
  }
  {
    std::lock_guard<std::mutex> lock(drag_mutex_);
    for (auto it = tcps.begin(); it != tcps.end();)
    {
      Eigen::Isometry3d& shown = shown_at_[it->first];
      const bool still = (it->second.translation() - shown.translation()).norm() < 1e-3;
      shown = still ? shown : it->second;
      it = still ? tcps.erase(it) : std::next(it);
    }
  }
  for (const auto& [robot, tcp] : tcps)
    server_.setPose(robot, tf2::toMsg(tcp));
  if (!tcps.empty())
    server_.applyChanges();
}

void MouseDrag::onFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f)
{
  using F = visualization_msgs::InteractiveMarkerFeedback;
  if (!arms_.count(f->marker_name))
    return;
  const std::string& robot = f->marker_name;
  const std::string id = "mouse_" + robot;
  const std::string& tcp = arms_.at(robot)->arm().robot().tcp_link;
  geometry_msgs::PoseStamped pose;
  pose.header = f->header, pose.pose = f->pose;
  Eigen::Isometry3d target = Eigen::Isometry3d::Identity();
  try
  {
    target.translation() = view_.poseInWorld(pose, "feedback").translation();
  }
  catch (const std::exception& e)
  {
    ROS_WARN_STREAM_THROTTLE(1.0, "/free_drive/feedback: " << e.what());
    return;
  }
  // down: a spring on the TCP (position only) pulls it to the box; moves: its target follows; up: let go.
  // drag_mutex_ is not held across the physics node's services (they wait for it).
  std::unique_lock<std::mutex> lock(drag_mutex_);
  const bool dragging = dragging_.count(robot) > 0;
  if (f->event_type == F::MOUSE_DOWN && !dragging)
  {
    dragging_.insert(robot);
    lock.unlock();
    if (physics_.attach(id, tcp, Eigen::Vector3d::Zero(), target, false))
      return view_.event(robot, "grab", "mouse grabbed " + tcp);
    lock.lock();
    dragging_.erase(robot);
  }
  else if (f->event_type == F::POSE_UPDATE && dragging)
    physics_.moveTarget(id, target);
  else if (f->event_type == F::MOUSE_UP && dragging)
  {
    dragging_.erase(robot);
    lock.unlock();
    physics_.release(id, tcp);
    view_.event(robot, "release", "mouse released " + tcp);
  }
}
}  // namespace vrrw_interaction
