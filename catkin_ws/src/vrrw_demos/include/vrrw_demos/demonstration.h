#pragma once
#include <map>
#include <string>
#include <vector>

namespace vrrw_demos
{
/// \brief One recorded state of a robot: arm joints and the gripper's actuated joint; times are
/// seconds from the start of the demonstration.
struct RobotState
{
  double time = 0.0;
  std::vector<double> positions;
  std::vector<double> velocities;
  double gripper = 0.0;
};

/// \brief A gripper goal (control_msgs/GripperCommand) sent during the demonstration.
struct GripperGoal
{
  double time = 0.0;
  double position = 0.0;
  double max_effort = 0.0;  ///< N; 0: none given
};

/// \brief Something that happened (vrrw_msgs/Event): grab, release, annotate, ...
struct DemoEvent
{
  double time = 0.0;
  std::string robot;
  std::string kind;
  std::string detail;
};

/// \brief A pose in the world frame: position (m) and unit quaternion (x, y, z, w).
struct Pose
{
  double position[3] = { 0.0, 0.0, 0.0 };
  double orientation[4] = { 0.0, 0.0, 0.0, 1.0 };
};

struct TimedPose
{
  double time = 0.0;
  Pose pose;
};

/// \brief What one robot did: every recorded state, its gripper goals, in time order.
struct RobotTrack
{
  std::string robot;
  std::vector<std::string> joint_names;  ///< the arm's joints, prefixed as in the bag
  std::string gripper_joint;             ///< the gripper's actuated joint; empty: none
  std::vector<RobotState> states;
  std::vector<GripperGoal> gripper_goals;
};

/// \brief What the recorder wrote on /demos/metadata (missing fields empty).
struct BagMetadata
{
  struct Robot
  {
    std::vector<std::string> arm_joints, gripper_joints;
    std::string base_link, tcp_link, config_file;
  };
  double start_stamp = 0.0;
  std::string scene, scene_file, scene_yaml, robot_description, vrrw_version, seed;
  std::vector<std::string> objects;
  std::map<std::string, Robot> robots;
};

/// \brief A demonstration as read from a bag: the robots' tracks, events and objects' poses.
struct Demonstration
{
  std::string source;        ///< the bag it was read from
  BagMetadata metadata;      ///< what the recorder wrote about the cell (empty fields: not recorded)
  double start_stamp = 0.0;  ///< absolute time (s) of time 0
  std::vector<RobotTrack> robots;
  std::vector<DemoEvent> events;
  std::map<std::string, std::vector<TimedPose>> objects;  ///< object name -> its poses over time

  /// \brief The robot's track, or nullptr.
  const RobotTrack* robot(const std::string& name) const
  {
    for (const RobotTrack& track : robots)
      if (track.robot == name)
        return &track;
    return nullptr;
  }
};

/// \brief The last recorded pose of \a object at or before time t (the first one before it is recorded);
/// nullptr when the object has no recorded pose.
const Pose* objectPoseAt(const Demonstration& demo, const std::string& object, double t);
}  // namespace vrrw_demos
