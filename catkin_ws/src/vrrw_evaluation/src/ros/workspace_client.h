#pragma once
// The demo's hands on a running workspace: the same ROS interfaces a user's script has (controller
// actions, planning services, physics services, tf, contacts). Not part of the ROS-free core.
#include <Eigen/Geometry>
#include <actionlib/client/simple_action_client.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/GripperCommandAction.h>
#include <mutex>
#include <optional>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <set>
#include <tf2_ros/transform_listener.h>
#include <vrrw_physics/Contacts.h>
#include <vrrw_scene/scene.h>
#include <vrrw_trajectory/joint_trajectory.h>

#include <vrrw_common/ros/persistent_service.h>

namespace vrrw_evaluation
{
/// \brief One sample of the TCP and the object, for the top view and the lift test.
struct TrackSample
{
  double time = 0.0;
  Eigen::Vector3d tcp = Eigen::Vector3d::Zero();
  Eigen::Isometry3d object = Eigen::Isometry3d::Identity();
};

/// \brief What was recorded between startRecording() and stopRecording().
struct Recording
{
  vrrw_trajectory::JointTrajectory arm;  ///< measured arm joints, seconds from the start
  std::vector<TrackSample> track;        ///< TCP and object at 20 Hz
  std::set<std::string> arm_contacts;    ///< arm collisions with the obstacles seen
  std::uint64_t joint_state_messages = 0;
  std::uint64_t contact_messages = 0;
  std::uint64_t event_messages = 0;
  std::string bag_file;  ///< the bag written beside, empty: none
  std::string recorder;  ///< who wrote it: "vrrw_demos recorder_node", the one bag writer
  std::uint64_t bag_messages = 0;  ///< messages in the bag
  double seconds = 0.0;  ///< wall
  double start_stamp = 0.0;  ///< s of ROS time at the start: time 0 of every field above
};

class WorkspaceClient
{
public:
  WorkspaceClient(ros::NodeHandle& node, const vrrw_scene::Robot& robot, const std::string& object,
                  std::set<std::string> obstacles);

  /// \brief Waits for the controllers, services, joint_states and the object's tf; false with `error`.
  bool waitUntilReady(double seconds, std::string& error);

  std::vector<double> armJoints();
  Eigen::Isometry3d objectPose();
  Eigen::Isometry3d tcpPose();
  /// \brief The flange (the robot's tool_link) in the world: where a hand grabs the wrist.
  Eigen::Isometry3d flangePose();

  /// \brief Sends a whole trajectory as one FollowJointTrajectory goal and waits for its result.
  bool execute(const vrrw_trajectory::JointTrajectory& trajectory, std::string& error);
  /// \brief GripperCommand: finger position (rad) and pad force (N); a stall on the object succeeds.
  bool grip(double position, double max_effort, std::string& error);
  /// \brief Collision-free IK of the TCP nearest `seed` (/<robot>/compute_ik); adds its time to ik_ms.
  std::optional<std::vector<double>> ik(const Eigen::Isometry3d& tcp, const std::vector<double>& seed,
                                        bool avoid_collisions, std::string& error, double* ik_ms = nullptr);
  /// \brief A collision-free timed motion to `goal` (/<robot>/plan).
  std::optional<vrrw_trajectory::JointTrajectory> plan(const std::vector<double>& goal, std::string& error,
                                                       double* plan_ms = nullptr);
  /// \brief /physics/set_object_pose, then waits until tf shows the object there.
  bool placeObject(const Eigen::Isometry3d& pose, std::string& error);

  /// \brief Starts recording; with `bag_file` also into that bag through vrrw_demos' /demos/start (everything
  /// the workspace publishes); throws std::runtime_error naming the service when the recorder does not take it.
  /// An existing `bag_file` (an earlier run's report) is replaced.
  void startRecording(const std::string& bag_file = "");
  Recording stopRecording();
  /// \brief An event (vrrw_msgs/Event on /demos/events in the bag): `kind` one word, `detail` one line.
  void annotate(const std::string& kind, const std::string& detail);
  /// \brief Seconds since startRecording().
  double recordingTime() const;
  /// \brief Simulated (ROS) seconds per wall second since waitUntilReady() succeeded.
  double realTimeFactor() const;

  const vrrw_scene::Robot& robot() const { return robot_; }
  /// \brief The arm joints' URDF velocity limits (rad/s), in arm_joints order; read by waitUntilReady().
  const std::vector<double>& maxVelocities() const { return max_velocity_; }

private:
  void onJointStates(const sensor_msgs::JointState::ConstPtr& msg);
  void onContacts(const vrrw_physics::Contacts::ConstPtr& msg);
  void onTrackTimer(const ros::TimerEvent&);
  std::optional<Eigen::Isometry3d> lookup(const std::string& frame);

  vrrw_scene::Robot robot_;
  std::string object_;
  std::set<std::string> obstacles_;
  ros::NodeHandle& node_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  actionlib::SimpleActionClient<control_msgs::FollowJointTrajectoryAction> arm_;
  actionlib::SimpleActionClient<control_msgs::GripperCommandAction> gripper_;
  std::string ik_, plan_;  ///< /<robot>/compute_ik, /<robot>/plan
  vrrw_common::PersistentServices links_;
  /// /demos/start took this recording's bag: stop and annotate go to the recorder. The runner's thread only.
  bool demos_recording_ = false;
  ros::Subscriber joint_states_, contacts_;
  ros::Timer track_timer_;

  /// Protects latest_, recording_, record_start_ and recording_data_: the spinner's threads (joint_states,
  /// contacts, the track timer) write them while the runner's thread reads them.
  mutable std::mutex mutex_;
  std::vector<double> latest_;  ///< PROTECTED BY mutex_: the arm's last measured joints, arm_joints order
  std::vector<double> max_velocity_;  ///< written once by waitUntilReady(), before any recording
  bool recording_ = false;  ///< PROTECTED BY mutex_
  /// PROTECTED BY mutex_ for the callbacks; the runner's thread, its only writer, also reads it unlocked
  /// (recordingTime). Physics stamps joint_states with the same clock.
  ros::Time record_start_;
  Recording recording_data_;  ///< PROTECTED BY mutex_
  ros::Time ready_sim_;  ///< the simulated and wall instants waitUntilReady() succeeded: realTimeFactor()'s start
  ros::WallTime ready_wall_;
};
}  // namespace vrrw_evaluation
