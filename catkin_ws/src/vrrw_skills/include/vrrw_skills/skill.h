#pragma once
#include <optional>
#include <string>
#include <vector>

#include <vrrw_dmp/cartesian_dmp.h>
#include <vrrw_dmp/dmp.h>

namespace vrrw_skills
{
using vrrw_dmp::CartesianPose;

/// \brief The frame a keyframe belongs to.
enum class Frame
{
  world,   ///< the world (a place on the table)
  object,  ///< the object's pose at the start of the demonstration (approach, grasp, retreat)
  place,   ///< the pose of the object named by Skill::place_on at the start (a place on another object)
};

/// \brief "world", "object" or "place".
std::string toString(Frame frame);
/// \brief Parses "world", "object" or "place"; throws SkillError naming \a field.
Frame frameFromString(const std::string& text, const std::string& field);

/// \brief A TCP pose in the frame it belongs to.
struct Keyframe
{
  Frame frame = Frame::world;
  CartesianPose pose;
};

/// \brief One instruction of the paper's pick-and-place (near_pick, pick, close_gripper, back_to_near_pick,
/// final, open_gripper), as demonstrated.
struct SkillInstruction
{
  std::string name;
  bool gripper = false;
  double duration = 0.0;  ///< s, as demonstrated (pauses inside included); the DMPs' tau leaves the pauses out

  // arm instructions
  Keyframe start;  ///< the TCP where it began
  Keyframe end;    ///< the TCP where it ended: approach, grasp, retreat or place
  std::vector<double> joints_start;  ///< the taught arm's joints at both ends (IK seeds)
  std::vector<double> joints_end;
  std::optional<vrrw_dmp::Dmp> joint_dmp;                ///< the taught arm's joint path
  std::optional<vrrw_dmp::CartesianDmp> cartesian_dmp;  ///< the TCP path in the world
  double joint_fit_rmse = 0.0;      ///< rad, joint DMP against its demonstration
  double cartesian_fit_rmse = 0.0;      ///< m
  double cartesian_fit_rmse_deg = 0.0;  ///< deg

  // gripper instructions
  double gripper_position = 0.0;  ///< the commanded position (GripperCommand goal), rad or m
  double gripper_reached = 0.0;   ///< where the fingers stopped (on the object when closing)
  double gripper_effort = 0.0;    ///< the goal's max_effort, N (0: none given)
};

/// \brief One instruction's span in a demonstration, s from its start stamp.
struct SourceSegment
{
  std::string name;
  double start = 0.0;
  double end = 0.0;
};

/// \brief Where one demonstration came from.
struct SkillSource
{
  std::string bag;    ///< absolute path
  std::string scene;  ///< the scene recorded in the bag's metadata
  std::string vrrw_version;
  double start_stamp = 0.0;  ///< s of ROS time: time 0 of the segments' times
  std::vector<SourceSegment> segments;
};

/// \brief A task taught by demonstration: per instruction its keyframes in the frame they belong to, a joint
/// DMP for the taught arm and a Cartesian DMP for any arm, the gripper's positions and efforts, and where it
/// all came from. Written as YAML (skill_yaml.h).
struct Skill
{
  static constexpr const char* kFormat = "vrrw_skills/1";

  std::string robot;  ///< the taught robot's name in its scene (namespace, joint prefix)
  std::vector<std::string> arm_joints;  ///< its arm joints, prefixed, base to tip
  std::string tcp_link;
  std::string gripper_joint;
  std::vector<double> joints_home;  ///< the taught arm where the demonstration began
  std::string object;    ///< the object picked
  std::string place_on;  ///< empty: placed in the world
  CartesianPose object_start;  ///< the object in the world at the start of the demonstration
  CartesianPose object_end;    ///< where it was left, world
  CartesianPose place_start;   ///< place_on's pose at the start (world), when place_on is set
  /// where the object came to rest (object_end) in the frame of the TCP when the gripper opened: with where it
  /// is held now, the place goal
  CartesianPose object_in_hand;
  std::vector<SkillInstruction> instructions;
  std::vector<SkillSource> sources;
  std::string created;  ///< UTC, ISO 8601
  std::string tool;     ///< what wrote it

  /// \brief The instruction named \a name, or nullptr.
  const SkillInstruction* instruction(const std::string& name) const;
  /// \brief The grasp: the TCP relative to the object when the gripper closed (pick's end keyframe); throws
  /// SkillError when the skill has no pick.
  const Keyframe& grasp() const;
  /// \brief The arm instructions in order.
  std::vector<const SkillInstruction*> armInstructions() const;
};
}  // namespace vrrw_skills
