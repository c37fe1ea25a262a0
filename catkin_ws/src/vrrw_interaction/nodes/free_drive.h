#pragma once
#include <interactive_markers/interactive_marker_server.h>
#include <map>
#include <memory>
#include <ros/ros.h>
#include <set>
#include <std_msgs/Float64.h>
#include <std_srvs/SetBool.h>

#include <vrrw_interaction/hand.h>

#include "ghost_interface.h"

namespace vrrw_interaction
{
/// \brief Free-drive: /<robot>/free_drive switches an arm compliant (physics) or hand-following (fake) and back
/// to rigid holding its pose; /<robot>/free_drive_active says which. Any /operator/<hand>/pose + grip is a
/// hand: closing within `grab_distance` of a link or object grabs it at the touched point (an operator spring
/// in physics; IK of the arm toward the carried TCP in fake mode), opening or a stale pose releases, the open
/// hand pushes through /physics/hand. In physics a marker on each robot's TCP pulls it by a spring (mouse).
class FreeDrive
{
public:
  /// \brief `angular_*`: N m/rad and N m s/rad of a hand's grip on a link (0: the link's orientation is free).
  FreeDrive(WorldView& view, std::vector<GhostInterface*> arms, double grab_distance, double hand_radius,
            double angular_stiffness, double angular_damping);
  /// \brief Free-drive of `robot` on or off; "" or why not.
  std::string set(const std::string& robot, bool on);

private:
  struct Tracker
  {
    explicit Tracker(const std::string& id) : hand(id) {}
    Hand hand;
    ros::Subscriber pose, grip;
    Eigen::Isometry3d tcp_at_grab = Eigen::Isometry3d::Identity();  ///< fake mode: the held arm's TCP
    Eigen::Isometry3d link_at_grab = Eigen::Isometry3d::Identity();  ///< the held link (physics: its orientation)
    bool pushes = false;       ///< physics: the open hand is a sphere (off until clear of what it let go)
    ros::WallTime last_command;
  };
  void discoverHands();
  void onPose(Tracker& tracker, const geometry_msgs::PoseStamped& msg);
  void onGrip(Tracker& tracker, const std_msgs::Float64& msg);
  void grab(Tracker& tracker);
  void release(Tracker& tracker, const std::string& why);
  void follow(Tracker& tracker);
  void publishHand(const Tracker& tracker, double radius);
  void tick();
  void onMouse(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  /// \brief /physics/set_spring: `point` (body frame) pulled to `target`; with `angular`, the body's
  /// orientation to target's rotation too (a hand's grip on a link carries its rotation).
  bool spring(const std::string& id, const std::string& body, const Eigen::Vector3d& point,
              const Eigen::Isometry3d& target, bool angular, bool release);

  WorldView& view_;
  std::map<std::string, GhostInterface*> arms_;
  double grab_distance_, hand_radius_, angular_stiffness_, angular_damping_;
  std::set<std::string> active_;
  std::map<std::string, std::unique_ptr<Tracker>> trackers_;
  std::map<std::string, ros::Publisher> active_pubs_, commands_;
  std::vector<ros::ServiceServer> services_;
  ros::Publisher spring_target_, hand_pub_, hand_markers_;
  ros::Timer discover_timer_, tick_timer_;
  std::unique_ptr<interactive_markers::InteractiveMarkerServer> mouse_;
  std::set<std::string> dragging_;
  std::map<std::string, Eigen::Isometry3d> mouse_at_;  ///< where each mouse marker was last put
};
}  // namespace vrrw_interaction
