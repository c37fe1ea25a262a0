#pragma once
#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <condition_variable>
#include <functional>
#include <map>
#include <geometry_msgs/PoseStamped.h>
#include <mutex>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <string>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <vrrw_interaction/held_objects.h>
#include <vrrw_kinematics/collision_world.h>
#include <vrrw_physics/Contacts.h>
#include <vrrw_scene/scene.h>

namespace vrrw_interaction
{
/// \brief What every arm's ghost, marker and hand share: the scene, its collision world with the live joint
/// state, object poses and held objects, tf, and the event stream (/operator/events).
///
/// Threads: the node's spinner threads, the marker solver and the execution threads all come through here.
/// mutex() guards the collision world, the live state and the held objects, and by convention every Arm,
/// GhostRobot and Hand of the node (their solvers keep state between calls). It is held only for computation:
/// never while waiting for tf, a service or an action.
class WorldView
{
public:
  WorldView(ros::NodeHandle& nh, const vrrw_scene::Scene& scene, std::string mode);

  const vrrw_scene::Scene& scene() const { return scene_; }
  /// \brief The collision world (mutex held).
  const vrrw_kinematics::CollisionWorld& world() const { return world_; }
  /// \brief fake, physics or none: how the robots move (free-drive differs).
  const std::string& mode() const { return mode_; }
  /// \brief The world's variables at the last /joint_states (mutex held).
  const Eigen::VectorXd& liveState() const { return live_; }
  std::mutex& mutex() { return mutex_; }
  /// \brief The newest instant the node knows (mutex held): ROS time now, or the newest state's stamp when that is
  /// later (in lockstep the state where the simulation waits may arrive before its /clock).
  ros::Time now() const { return std::max(ros::Time::now(), live_stamp_); }
  /// \brief Waits (at most 0.5 s of wall time, with or without the mutex) until the ROS clock reached the newest
  /// state's stamp: in lockstep that state, where the simulation waits, may arrive before its /clock, and what
  /// this node stamps with the ROS clock (events, actionlib goals) must carry that instant on every run.
  void awaitClock() const;
  /// \brief `at_instant(stamp)` runs (mutex held) whenever a /joint_states message with a newer stamp than any
  /// before has been taken into the live state: an instant of the simulation (physics), of a fake controller or
  /// of scene_node's held states (mode none). What observers get of the ghost is sent at these instants. Register
  /// before the node spins.
  void onInstant(std::function<void(const ros::Time& stamp)> at_instant) { at_instant_.push_back(std::move(at_instant)); }
  /// \brief Lockstep (physics held between steps): waits until the live state, the contacts and the objects
  /// are those of the instant the simulation waits at, at most 2 s of wall time, so what is computed from them
  /// does not depend on when messages arrive. Paced or not physics: returns at once. Call it without the mutex.
  void catchUp();

  /// \brief A stamped pose in the world. A scene link's pose is taken at the live state (this locks the mutex
  /// for it: call it without holding the mutex); any other frame from tf as it is now, never waiting. Throws
  /// std::runtime_error "<field>.header.frame_id: ..." or "<field>.pose: ..." (one line naming the field).
  Eigen::Isometry3d poseInWorld(const geometry_msgs::PoseStamped& pose, const std::string& field = "pose");
  /// \brief While `allow`: every object `robot` holds may touch the scene object `surface` (mutex held).
  void allowPlaceContact(const std::string& robot, const std::string& surface, bool allow);
  /// \brief One vrrw_msgs/Event on /operator/events.
  void event(const std::string& robot, const std::string& kind, const std::string& detail);

private:
  void onJointStates(const sensor_msgs::JointState& msg);
  /// \brief Physics: who holds what by the fingers' contacts (HeldObjects::squeezedBy).
  void onContacts(const vrrw_physics::Contacts& msg);
  /// \brief 10 Hz: free objects where tf has them; fake mode: who holds what by the closed grippers.
  void refreshObjects(const ros::Time& at = ros::Time(0));
  void publish(const std::vector<HeldEvent>& events);
  /// \brief Who holds what by `contacts` of instant `stamp`, with the joint state of that instant (mutex held).
  std::vector<HeldEvent> takeContacts(const ros::Time& stamp, const std::vector<BodyContact>& contacts,
                                      const Eigen::VectorXd& state);

  const vrrw_scene::Scene scene_;
  const std::string mode_;
  std::mutex mutex_;
  vrrw_kinematics::CollisionWorld world_;  ///< PROTECTED BY mutex_
  Eigen::VectorXd live_;                   ///< PROTECTED BY mutex_
  ros::Time live_stamp_, contacts_stamp_;  ///< PROTECTED BY mutex_: the newest /joint_states, /physics/contacts
  std::atomic<std::uint64_t> live_nsec_{ 0 };  ///< live_stamp_, for awaitClock() without the mutex
  /// called with mutex_ held; filled before the node spins, only read after
  std::vector<std::function<void(const ros::Time&)>> at_instant_;
  std::condition_variable arrived_;        ///< with mutex_: a joint state or contacts arrived
  HeldObjects held_;                       ///< PROTECTED BY mutex_ (it changes world_'s attachments)
  // Contacts and joint states of one instant come on two connections, in either order: each contacts message is
  // taken with the state of its own instant, so who holds what does not depend on which came first.
  std::map<ros::Time, Eigen::VectorXd> recent_states_;                 ///< PROTECTED BY mutex_: by stamp, bounded
  std::map<ros::Time, std::vector<BodyContact>> early_contacts_;  ///< PROTECTED BY mutex_: before their state
  tf2_ros::Buffer tf_;                     ///< thread-safe by itself: looked up without mutex_
  tf2_ros::TransformListener listener_;
  ros::Subscriber joint_states_, contacts_;
  std::mutex step_mutex_;
  ros::ServiceClient step_;  ///< PROTECTED BY step_mutex_: /physics/step asked where the simulation waits
  ros::Publisher events_;
  ros::ServiceServer sync_;  ///< /interaction/sync: catchUp() for a client (a recorder about to stop)
  ros::Timer objects_timer_;
};
}  // namespace vrrw_interaction
