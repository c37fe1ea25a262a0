#pragma once
#include <map>
#include <memory>
#include <ros/ros.h>
#include <set>
#include <std_msgs/Float64.h>
#include <vrrw_interaction/grab_target.h>
#include <vrrw_interaction/hand.h>

#include "ghost_interface.h"
#include "physics_operator.h"

namespace vrrw_interaction
{
/// \brief Free-drive: /<robot>/free_drive switches an arm compliant (physics) or hand-following (fake) and back
/// to rigid holding its pose; /<robot>/free_drive_active says which. Any /operator/<hand>/pose + grip is a
/// hand: closing it grabs what handGrab() finds (an operator spring in physics; IK of the arm toward the carried
/// TCP in fake mode), opening or a stale pose releases, the open hand pushes through /physics/hand. Time is ROS
/// time (simulated in physics): a hand goes stale after 0.5 s of it without a pose, and stays held while a
/// lockstep simulation waits; the markers and the stale checks run at the simulation's instants
/// (WorldView::onInstant), so a lockstep run sends the same messages each time.
///
/// Every member but the ROS handles is PROTECTED BY the world's mutex (view.mutex()); decisions are taken
/// under it, the physics node's services are called after it is released.
class FreeDrive
{
public:
  FreeDrive(WorldView& view, std::vector<GhostInterface*> arms, double grab_distance, double hand_radius,
            const SpringGains& gains);
  /// \brief Free-drive of `robot` on or off (takes the mutex itself).
  Outcome set(const std::string& robot, bool on);

private:
  /// \brief One /operator/<id>/ hand and what it holds.
  struct Tracker
  {
    explicit Tracker(const std::string& id) : hand(id), shown(id), spring("hand_" + id) {}
    Hand hand;
    /// \brief The hand as of the last instant (atInstant): the poses timed before it. A script sends its hand
    /// ahead of the simulation, and this node may take the states late: the markers and time-outs at an
    /// instant are the same however late.
    Hand shown;
    std::map<double, Eigen::Isometry3d> arriving;  ///< poses by time, not yet shown
    const std::string spring;  ///< its operator spring's id in physics
    ros::Subscriber pose, grip;
    Eigen::Isometry3d tcp_at_grab = Eigen::Isometry3d::Identity();   ///< fake mode: the held arm's TCP
    Eigen::Isometry3d link_at_grab = Eigen::Isometry3d::Identity();  ///< the held link (physics: its orientation)
    bool pushes = false;        ///< physics: the open hand is a sphere (off until clear of what it let go)
    ros::Time last_command;     ///< fake mode: the last arm command it caused
  };
  void discoverHands();
  void onPose(Tracker& tracker, const geometry_msgs::PoseStamped& msg);
  void onGrip(Tracker& tracker, const std_msgs::Float64& msg);
  /// \brief What the closing hand takes, taken (mutex held); none when it closed on nothing. Its `grab` event
  /// follows once it is held (grabbed()).
  std::optional<GrabTarget> grab(Tracker& tracker);
  /// \brief Physics: the spring of a grab just taken (mutex not held); false, having let go again, when physics
  /// refused it.
  bool attachSpring(Tracker& tracker, const GrabTarget& target);
  /// \brief The `grab` event: the hand holds `target` now (in physics: its spring is attached).
  void grabbed(Tracker& tracker, const GrabTarget& target);
  /// \brief Lets go (mutex held); what it held, whose spring physics_ then releases without the mutex. Its
  /// `release` event follows once it is let go (released()).
  GrabTarget release(Tracker& tracker);
  /// \brief The `release` event, after physics released the spring: a script that steps the simulation after it
  /// knows that no step pulls any more.
  void released(Tracker& tracker, const GrabTarget& held, const std::string& why);
  /// \brief The held body follows the hand (mutex held): a spring target at the hand pose's `stamp`, or in fake
  /// mode an arm command.
  void follow(Tracker& tracker, const ros::Time& stamp);
  /// \brief At each instant (mutex held): stale hands let go (their springs are released by
  /// releaseStale()) and stop pushing; the hands' markers, 20 times a second of ROS time.
  void atInstant(const ros::Time& now);
  /// \brief Releases the springs of the hands atInstant() let go, and says so (mutex not held).
  void releaseStale();

  WorldView& view_;
  std::map<std::string, GhostInterface*> arms_;  ///< (set up once, read-only after)
  GrabRule rule_;
  const double hand_radius_;
  PhysicsOperator physics_;  ///< (thread-safe by itself)
  std::set<std::string> active_;                               ///< robots in free-drive
  std::map<std::string, std::unique_ptr<Tracker>> trackers_;   ///< by hand id
  std::map<std::string, ros::Publisher> active_pubs_, commands_;
  std::vector<ros::ServiceServer> services_;
  ros::Publisher hand_markers_;
  ros::WallTimer discover_timer_;  ///< wall clock, as below: hands are found in the person's time
  ros::Time markers_at_;           ///< when the markers were sent last
  std::vector<std::pair<Tracker*, GrabTarget>> stale_;  ///< let go by atInstant(), for releaseStale()
  ros::WallTimer release_timer_;   ///< runs releaseStale() (physics' services, off the mutex)
};
}  // namespace vrrw_interaction
