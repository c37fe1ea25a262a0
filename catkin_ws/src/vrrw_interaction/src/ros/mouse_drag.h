#pragma once
#include <interactive_markers/interactive_marker_server.h>
#include <map>
#include <memory>
#include <mutex>
#include <set>

#include "ghost_interface.h"
#include "physics_operator.h"

namespace vrrw_interaction
{
/// \brief Mouse free-drive in physics (/free_drive/update, /free_drive/feedback): a box on each robot's live
/// TCP; dragging it pulls the TCP by an operator spring (turn free-drive on first), releasing it lets go.
class MouseDrag
{
public:
  MouseDrag(WorldView& view, std::vector<GhostInterface*> arms, const SpringGains& gains);

private:
  void onFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  /// \brief 20 Hz: the boxes nobody drags sit on the live TCPs.
  void placeMarkers();

  // The server calls onFeedback holding its own mutex, and onFeedback takes the world's and drag_mutex_: the
  // server is never called holding either (placeMarkers reads the TCPs first, then moves the boxes).
  WorldView& view_;
  std::map<std::string, GhostInterface*> arms_;  ///< (set up once, read-only after)
  PhysicsOperator physics_;                      ///< (thread-safe by itself)
  interactive_markers::InteractiveMarkerServer server_;  ///< (thread-safe by itself)
  std::mutex drag_mutex_;
  std::set<std::string> dragging_;                     ///< PROTECTED BY drag_mutex_: robots whose box is held
  std::map<std::string, Eigen::Isometry3d> shown_at_;  ///< PROTECTED BY drag_mutex_: where each box was put
  ros::WallTimer timer_;
};
}  // namespace vrrw_interaction
