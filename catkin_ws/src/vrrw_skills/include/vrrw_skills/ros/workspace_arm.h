#pragma once
// One arm of the running workspace as a skill run needs it: its joints (joint_states), where frames are (tf),
// its controllers' actions (FollowJointTrajectory, GripperCommand), the mode they run in. Free-running, or in
// lockstep (holdSimulation): every goal then takes effect while the simulation waits and is stepped until the
// controllers are idle, and every read is the state where the simulation stopped, so a run repeats bit for bit.
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <ros/ros.h>
#include <vrrw_common/ros/action_client.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_listener.h>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/ros/lockstep_client.h>
#include <vrrw_skills/skill.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_skills
{
class WorkspaceArm
{
public:
  /// \brief Robot \a robot of the running scene (its /scene/robots parameters and /robot_description); throws
  /// SkillError naming the robot when the scene has no such robot.
  WorkspaceArm(ros::NodeHandle& node, const std::string& robot, vrrw_common::PersistentServices& services);
  ~WorkspaceArm();
  WorkspaceArm(const WorkspaceArm&) = delete;
  WorkspaceArm& operator=(const WorkspaceArm&) = delete;

  /// \brief Lockstep from here on: \a sim holds the simulation paused (the caller paused it); goals, waits and
  /// settle() step it. The arm's joints and tf are caught up at every stop.
  void holdSimulation(vrrw_physics::LockstepClient& sim);
  /// \brief In lockstep, every stop also waits for \a frame's tf there (an object a run reads).
  void watchFrame(const std::string& frame) { watched_.push_back(frame); }
  /// \brief The simulation this arm steps, or null (free-running).
  vrrw_physics::LockstepClient* simulation() const { return sim_; }

  const std::string& robot() const { return robot_; }
  const std::vector<std::string>& armJoints() const { return arm_joints_; }
  const std::string& tcpLink() const { return tcp_link_; }
  /// \brief The arm joints' URDF velocity limits, rad/s.
  const std::vector<double>& maxVelocities() const { return max_velocity_; }
  /// \brief The arm joints' acceleration limits (the scene's robot config), rad/s^2.
  const std::vector<double>& maxAccelerations() const { return max_acceleration_; }
  /// \brief "fake", "physics" or "real": the arm controller's mode.
  const std::string& mode() const { return mode_; }

  /// \brief Waits (wall clock: a paused simulation holds ROS time still) up to \a seconds for a joint state and
  /// the controllers; throws SkillRefusal.
  void waitUntilReady(double seconds);
  /// \brief The latest measured arm joints.
  std::vector<double> joints() const;
  /// \brief The fastest joint's speed in the latest joint state, rad/s.
  double speed() const;
  /// \brief A frame's pose in the world from tf (the latest: in lockstep where the simulation waits), or nothing.
  std::optional<CartesianPose> pose(const std::string& frame) const;
  /// \brief A frame's pose in the world at simulated \a time (tf keeps 60 s), or nothing.
  std::optional<CartesianPose> poseAt(const std::string& frame, const ros::Time& time) const;
  /// \brief The ROS time; in lockstep the simulated time where the simulation waits.
  ros::Time now() const;
  /// \brief Lets \a seconds of simulated time pass (an object comes to rest): stepped in lockstep, slept otherwise.
  void settle(double seconds);

  /// \brief One FollowJointTrajectory goal, waited for (simulated time); in real mode confirmed once its
  /// simulation ended; \a goal_tolerance (rad, every joint) > 0 replaces the controller's. Throws SkillRefusal
  /// naming \a instruction and the controller's answer.
  void execute(const std::string& instruction, const vrrw_trajectory::JointTrajectory& trajectory,
               double goal_tolerance = 0.0);
  /// \brief One GripperCommand goal; a stall on the object succeeds. Throws SkillRefusal.
  void grip(const std::string& instruction, double position, double max_effort);

  /// \brief Set from a signal handler: the goal being waited for is cancelled and the wait ends
  /// (SkillRefusal "interrupted"). Ctrl-C on a tool cancels what it started.
  static void interrupt();

private:
  /// Waits for \a client's goal until done, \a seconds of simulated time or an interrupt (cancels then).
  template <class Client>
  void waitFor(Client& client, const std::string& instruction, const std::string& what, double seconds);
  /// In lockstep: steps until \a client's goal is done (the controllers idle), at most \a seconds.
  template <class Client>
  void stepUntilDone(Client& client, const std::string& instruction, const std::string& what, double seconds);
  /// In lockstep, after every stop at \a time: waits (wall clock, bounded) until this arm's joint state and tf
  /// of its TCP at that stamp arrived. Throws SkillRefusal when they do not.
  void catchUp(const ros::Time& time);
  void onJointStates(const sensor_msgs::JointState::ConstPtr& message);
  void confirmReal(const std::string& instruction, double seconds);

  std::string robot_;
  std::vector<std::string> arm_joints_;
  std::string tcp_link_;
  std::vector<double> max_velocity_;
  std::vector<double> max_acceleration_;
  std::string mode_;
  vrrw_common::PersistentServices& services_;
  vrrw_physics::LockstepClient* sim_ = nullptr;  ///< set by holdSimulation(): lockstep
  int stop_observer_ = -1;                       ///< catchUp() among sim_'s stop observers
  std::vector<std::string> watched_;             ///< frames catchUp() waits for beside the TCP
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction> arm_;
  vrrw_common::ActionClient<control_msgs::GripperCommandAction> gripper_;

  mutable std::mutex mutex_;          ///< protects latest_, speed_ and stamp_
  std::condition_variable state_arrived_;  ///< a joint state arrived (catchUp waits for it)
  std::vector<double> latest_;        ///< PROTECTED BY mutex_
  double speed_ = 0.0;                ///< PROTECTED BY mutex_
  ros::Time stamp_;                   ///< PROTECTED BY mutex_: latest_'s stamp

  ros::Subscriber joint_states_;  ///< last: destroyed first, so no callback runs into freed members
};
}  // namespace vrrw_skills
