#pragma once
#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <map>
#include <mutex>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <string>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <vrrw_kinematics/collision_world.h>
#include <vrrw_physics/Contacts.h>
#include <vrrw_scene/scene.h>

namespace vrrw_interaction
{
/// \brief What every arm's ghost, marker and hand share: the scene, its collision world with the live joint
/// state and object poses, tf, the ghost frames and the event stream. `mutex` guards all of it (and every
/// Arm, GhostRobot and Hand of the node).
class WorldView
{
public:
  WorldView(ros::NodeHandle& nh, const vrrw_scene::Scene& scene, std::string mode);

  const vrrw_scene::Scene& scene() const { return scene_; }
  const vrrw_kinematics::CollisionWorld& world() const { return world_; }
  /// \brief fake, physics or none: how the robots move (free-drive differs).
  const std::string& mode() const { return mode_; }
  const Eigen::VectorXd& liveState() const { return live_; }
  std::mutex& mutex() { return mutex_; }

  /// \brief A stamped pose in the world; throws std::runtime_error "pose.header.frame_id: ..." or
  /// "pose.pose.orientation: ..." (one line naming the field).
  Eigen::Isometry3d poseInWorld(const geometry_msgs::PoseStamped& pose, const std::string& field = "pose") const;
  /// \brief Publishes every link at `ghost_state` as tf frame ghost/<link> (rviz: RobotModel with TF prefix ghost).
  void publishGhostFrames(const Eigen::VectorXd& ghost_state);
  /// \brief While `allow`: every object `robot` holds may touch the scene object `surface` (mutex held);
  /// false takes back exactly what true allowed.
  void allowPlaceContact(const std::string& robot, const std::string& surface, bool allow);
  /// \brief One vrrw_msgs/Event on /operator/events.
  void event(const std::string& robot, const std::string& kind, const std::string& detail);

private:
  /// \brief An object a gripper holds: attached to the TCP link; `supports` are the fixed objects it rested
  /// on when taken (allowed until it is lifted 1 cm clear, so a plan may start at the grasp).
  struct Held
  {
    std::string robot;
    std::vector<std::string> supports;
    std::vector<std::string> restore;  ///< fixed objects the ACM let it touch while free (allowed again on release)
    Eigen::Vector3d taken_at = Eigen::Vector3d::Zero();  ///< the object's position when attached
    double last_seen = 0.0;  ///< wall time the holding rule last held
  };
  void onJointStates(const sensor_msgs::JointState& msg);
  void onContacts(const vrrw_physics::Contacts& msg);
  void refreshObjects();
  /// \brief Fake mode's rule: the gripper more than 30 % closed and its TCP within 1 cm of the object.
  bool fakeHolds(const vrrw_scene::Robot& robot, const std::string& object) const;
  /// \brief Attaches or (after 0.3 s without the rule) detaches; events "attach"/"detach".
  void updateHeld(const std::string& object, const std::string& robot, double now);
  void releaseSupports(const std::string& object, Held& held, bool all);

  vrrw_scene::Scene scene_;
  vrrw_kinematics::CollisionWorld world_;
  std::string mode_;
  Eigen::VectorXd live_;
  std::mutex mutex_;
  tf2_ros::Buffer tf_;
  tf2_ros::TransformListener listener_;
  tf2_ros::TransformBroadcaster broadcaster_;
  ros::Time last_ghost_stamp_;
  std::map<std::string, Held> held_;                          ///< by object
  std::vector<std::pair<std::string, std::string>> place_contacts_;  ///< pairs allowPlaceContact allowed
  std::map<std::string, std::vector<std::string>> gripper_links_;  ///< by robot: the links below its flange
  ros::Subscriber joint_states_, contacts_;
  ros::Publisher events_;
  ros::Timer objects_timer_;
};
}  // namespace vrrw_interaction
