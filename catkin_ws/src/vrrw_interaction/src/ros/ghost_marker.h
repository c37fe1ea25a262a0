#pragma once
#include <condition_variable>
#include <interactive_markers/interactive_marker_server.h>
#include <interactive_markers/menu_handler.h>
#include <map>
#include <memory>
#include <thread>

#include "ghost_interface.h"

namespace vrrw_interaction
{
/// \brief A 6-DoF interactive marker on every ghost's TCP with the ghost's menu. Feedback is coalesced
/// latest-wins per arm and solved by one thread at most `rate` times a second (no queue of stale poses);
/// IK is seeded from the ghost and refuses branch flips; a refused pose leaves the ghost and keeps the
/// marker where the operator put it, red, its text saying why ("unreachable (residual ...)", "collision: A - B").
class GhostMarkers
{
public:
  GhostMarkers(WorldView& view, std::vector<GhostInterface*> ghosts, double rate, double max_jump,
               const std::function<void(const std::string& robot, bool on)>& free_drive);
  ~GhostMarkers();

private:
  struct Pending
  {
    Eigen::Isometry3d pose;
    ros::Time stamp;
  };
  void onFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  void solveLoop();
  /// \brief (Re)draws robot's marker at `pose`, green or red with `status` as its text.
  void draw(const std::string& robot, const Eigen::Isometry3d& pose, const std::string& status);
  void buildMenu(GhostInterface& ghost, const std::function<void(const std::string&, bool)>& free_drive);

  // Locks, in the order they may be taken: the world's mutex (solving a pose), then draw_mutex_; pending_mutex_
  // is never held while taking another. The server calls onFeedback holding its own mutex, so the server is
  // touched only by the solver thread (and the constructor), never from a callback that holds the world's.
  WorldView& view_;
  std::map<std::string, GhostInterface*> ghosts_;  ///< (set up once, read-only after)
  double period_, max_jump_;
  interactive_markers::InteractiveMarkerServer server_;  ///< PROTECTED BY draw_mutex_
  std::map<std::string, std::unique_ptr<interactive_markers::MenuHandler>> menus_;  ///< PROTECTED BY draw_mutex_
  std::mutex draw_mutex_;
  std::map<std::string, std::string> status_;  ///< PROTECTED BY draw_mutex_: each marker's refusal text ("" green)
  std::mutex pending_mutex_;
  std::condition_variable wake_;            ///< (with pending_mutex_) the solver waits here for work
  std::map<std::string, Pending> pending_;  ///< PROTECTED BY pending_mutex_: the newest pose per marker
  std::map<std::string, Eigen::Isometry3d> moved_;  ///< PROTECTED BY pending_mutex_: ghosts moved by a service or the menu
  bool stop_ = false;                               ///< PROTECTED BY pending_mutex_
  std::thread solver_;
};
}  // namespace vrrw_interaction
