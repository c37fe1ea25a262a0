#pragma once
// The demo runner's hands on a running physics workspace: the interfaces a user's script has (controller
// actions, planning services, physics services, tf, contacts). The runner holds the simulation and steps it
// itself (lockstep): it acts while the simulation waits and reads the state exactly where it waits, so a run
// with the same seed moves the same way at any real-time factor. Not part of the ROS-free core.
#include <Eigen/Geometry>
#include <vrrw_common/ros/action_client.h>
#include <condition_variable>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <mutex>
#include <optional>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <set>
#include <tf2_ros/transform_listener.h>
#include <vrrw_kinematics/robot_model.h>
#include <vrrw_physics/Contacts.h>
#include <vrrw_scene/scene.h>
#include <vrrw_trajectory/joint_trajectory.h>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/ros/lockstep_client.h>

namespace vrrw_evaluation
{
/// Wall seconds a client of the workspace waits for what a process beside it does at once (take a goal, pass a
/// pose on, answer, publish the state where the simulation stopped): far beyond what it takes on a loaded
/// machine, short of a hang.
inline constexpr double kAnswerSeconds = 10.0;

/// \brief One sample of the TCP and the object, for the top view and the lift test.
struct TrackSample
{
  double time = 0.0;
  Eigen::Vector3d tcp = Eigen::Vector3d::Zero();
  Eigen::Isometry3d object = Eigen::Isometry3d::Identity();
};

/// \brief What was recorded between startRecording() and stopRecording(), times in simulated s from its start.
struct Recording
{
  vrrw_trajectory::JointTrajectory arm;  ///< the arm's joints at every joint_states message
  std::vector<TrackSample> track;        ///< TCP and object every 50 ms (at the first joint_states on or after)
  std::set<std::string> arm_contacts;    ///< arm collisions with the obstacles seen
  std::uint64_t joint_state_messages = 0;
  std::uint64_t contact_messages = 0;
  std::uint64_t event_messages = 0;
  std::string bag_file;            ///< the bag vrrw_demos' recorder wrote, empty: none
  std::uint64_t bag_messages = 0;  ///< messages in it (the recorder's count)
  double seconds = 0.0;            ///< simulated
  double start_stamp = 0.0;        ///< s of simulated time at the start: time 0 of every field above
};

class WorkspaceClient
{
public:
  /// \brief `sim`: the hold on the physics node every motion is stepped through.
  WorkspaceClient(ros::NodeHandle& node, const vrrw_scene::Robot& robot, const std::string& object,
                  std::set<std::string> obstacles, vrrw_physics::LockstepClient& sim);
  ~WorkspaceClient();
  WorkspaceClient(const WorkspaceClient&) = delete;
  WorkspaceClient& operator=(const WorkspaceClient&) = delete;

  /// \brief Waits for the controllers, services, joint_states and the object's tf, then holds the simulation
  /// (every motion from here on is stepped); false with `error`.
  bool waitUntilReady(double seconds, std::string& error);

  /// \brief The arm's joints where the simulation waits.
  std::vector<double> armJoints();
  /// \brief The object where the simulation waits (its tf at that stamp).
  Eigen::Isometry3d objectPose();
  /// \brief The TCP where the simulation waits (forward kinematics of the joint state there).
  Eigen::Isometry3d tcpPose();
  /// \brief The flange (the robot's tool_link) in the world: where a hand grabs the wrist.
  Eigen::Isometry3d flangePose();

  /// \brief Sends a whole trajectory as one FollowJointTrajectory goal, steps until it ended, returns its result.
  bool execute(const vrrw_trajectory::JointTrajectory& trajectory, std::string& error);
  /// \brief GripperCommand: finger position (rad) and pad force (N); a stall on the object succeeds.
  bool grip(double position, double max_effort, std::string& error);
  /// \brief Collision-free IK of the TCP nearest `seed` (/<robot>/compute_ik); adds its time to ik_ms.
  std::optional<std::vector<double>> ik(const Eigen::Isometry3d& tcp, const std::vector<double>& seed,
                                        bool avoid_collisions, std::string& error, double* ik_ms = nullptr);
  /// \brief A collision-free timed motion to `goal` (/<robot>/plan).
  std::optional<vrrw_trajectory::JointTrajectory> plan(const std::vector<double>& goal, std::string& error,
                                                       double* plan_ms = nullptr);
  /// \brief /physics/set_object_pose while the simulation waits, then one step, so tf has it at a new stamp
  /// (tf drops a second transform at one stamp).
  bool placeObject(const Eigen::Isometry3d& pose, std::string& error);
  /// \brief Lets `seconds` of simulated time pass (the drill settles, comes to rest).
  void settle(double seconds);

  /// \brief Starts recording in memory; with `bag_file` also to that bag by vrrw_demos' recorder (/demos/start:
  /// everything the workspace publishes). An existing `bag_file` is replaced. Throws std::runtime_error when the
  /// recorder refuses or is not there.
  void startRecording(const std::string& bag_file = "");
  Recording stopRecording();
  /// \brief An annotation in the bag (/demos/annotate: a vrrw_msgs/Event on /demos/events at the simulated time
  /// where the simulation waits): `kind` one word, `detail` one line.
  void annotate(const std::string& kind, const std::string& detail);
  /// \brief Simulated seconds since startRecording().
  double recordingTime() const;
  /// \brief Simulated seconds per wall second since waitUntilReady() succeeded.
  double realTimeFactor() const;

  const vrrw_scene::Robot& robot() const { return robot_; }
  /// \brief The arm joints' URDF velocity limits (rad/s), in arm_joints order; read by waitUntilReady().
  const std::vector<double>& maxVelocities() const { return max_velocity_; }
  vrrw_physics::LockstepClient& simulation() { return sim_; }

private:
  void onJointStates(const sensor_msgs::JointState::ConstPtr& msg);
  void onContacts(const vrrw_physics::Contacts::ConstPtr& msg);
  /// After every stop at `time`: waits (wall clock, bounded) until this client has the joint state and the
  /// object's tf published there, then gives the track samples since the last stop their object poses.
  void catchUp(const ros::Time& time);
  std::optional<Eigen::Isometry3d> lookup(const std::string& frame, const ros::Time& time);
  /// The pose of `link` in the world at joint state `state` (forward kinematics; mutex_ held, model_ set).
  Eigen::Isometry3d linkPose(const sensor_msgs::JointState& state, const std::string& link) const;

  vrrw_scene::Robot robot_;
  std::string object_;
  std::set<std::string> obstacles_;
  ros::NodeHandle& node_;
  vrrw_physics::LockstepClient& sim_;
  int stop_observer_ = -1;  ///< catchUp() among sim_'s stop observers
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  vrrw_common::ActionClient<control_msgs::FollowJointTrajectoryAction> arm_;
  vrrw_common::ActionClient<control_msgs::GripperCommandAction> gripper_;
  std::string ik_, plan_;  ///< /<robot>/compute_ik, /<robot>/plan
  vrrw_common::PersistentServices links_;
  bool demos_recording_ = false;  ///< a bag is being recorded by vrrw_demos (main thread only)
  ros::Time ready_sim_;
  ros::WallTime ready_wall_;

  mutable std::mutex mutex_;  ///< protects what the subscriber callbacks write, below
  std::condition_variable state_arrived_;  ///< a joint_states message arrived
  std::condition_variable contacts_arrived_;  ///< a contacts message arrived
  ros::Time contacts_stamp_;               ///< PROTECTED BY mutex_: the latest contacts message's stamp
  sensor_msgs::JointState latest_;         ///< PROTECTED BY mutex_: the robot's last joint_states
  std::vector<double> latest_arm_;         ///< PROTECTED BY mutex_: its arm joints, in arm_joints order
  std::optional<vrrw_kinematics::RobotModel> model_;  ///< PROTECTED BY mutex_: the URDF, set by waitUntilReady()
  std::vector<double> max_velocity_;
  bool recording_ = false;             ///< PROTECTED BY mutex_
  ros::Time record_start_;             ///< PROTECTED BY mutex_: physics stamps joint_states with simulated time
  ros::Time next_sample_;              ///< PROTECTED BY mutex_: the track's next sample is due at this stamp
  std::vector<ros::Time> unresolved_;  ///< PROTECTED BY mutex_: stamps of track samples without their object pose
  Recording recording_data_;           ///< PROTECTED BY mutex_

  ros::Subscriber joint_states_, contacts_;  ///< last: destroyed first, so no callback runs into freed members
};
}  // namespace vrrw_evaluation
