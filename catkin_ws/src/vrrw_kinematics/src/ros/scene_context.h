#pragma once
#include <Eigen/Geometry>
#include <map>
#include <optional>
#include <geometry_msgs/PoseStamped.h>
#include <ros/time.h>
#include <sensor_msgs/JointState.h>
#include <string>
#include <tf2_ros/buffer.h>
#include <vrrw_scene/scene.h>

#include <vrrw_kinematics/collision_world.h>
#include <vrrw_kinematics/kinematics_error.h>

namespace vrrw_kinematics
{
/// \brief What every robot's services share: the scene, its collision world, the live joint state and tf.
class SceneContext
{
public:
  SceneContext(const vrrw_scene::Scene& scene, tf2_ros::Buffer& tf);

  const vrrw_scene::Scene& scene() const { return scene_; }
  const CollisionWorld& world() const { return world_; }
  /// \brief Moves every free scene object to its live tf pose (world -> object), when tf has one.
  void refreshObjects();
  /// \brief Attaches `object` to `link` at the live state; the links below `gripper_root` may touch it.
  void attach(const std::string& object, const std::string& link, const std::string& gripper_root);
  /// \brief Frees an attached object where the live state puts it.
  void detach(const std::string& object);
  const Eigen::VectorXd& liveState() const { return live_; }
  /// \brief Takes the positions of known joints from a joint_states message, and notes which robots it is of.
  void updateLive(const sensor_msgs::JointState& msg);
  /// \brief Wall-clock seconds since a joint_states message last named a joint of `robot`; nullopt before the
  /// first (the robot is at its scene initial state). Wall clock: simulated time stops with the simulation.
  std::optional<double> stateAge(const std::string& robot) const;
  /// \brief The live state with the message's joints set; throws KinematicsError(InvalidArgument) naming an
  /// unknown joint or a name/position count mismatch.
  Eigen::VectorXd overlay(const sensor_msgs::JointState& msg) const;
  /// \brief Pose of a frame (a scene link or any tf frame; "" is the world) in the world at `state`.
  Eigen::Isometry3d frameInWorld(const std::string& frame, const Eigen::VectorXd& state) const;
  /// \brief A stamped pose in the world; throws KinematicsError (InvalidPose, UnknownLink).
  Eigen::Isometry3d poseInWorld(const geometry_msgs::PoseStamped& pose, const Eigen::VectorXd& state) const;

private:
  vrrw_scene::Scene scene_;
  CollisionWorld world_;
  Eigen::VectorXd live_;
  std::vector<std::string> robot_of_variable_;  ///< owning robot of each model variable ("" for none)
  std::map<std::string, ros::WallTime> last_state_;  ///< per robot
  tf2_ros::Buffer& tf_;
};
}  // namespace vrrw_kinematics
