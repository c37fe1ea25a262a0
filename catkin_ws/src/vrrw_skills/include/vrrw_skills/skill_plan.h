#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <vrrw_skills/skill.h>
#include <vrrw_trajectory/joint_trajectory.h>

namespace vrrw_skills
{
/// \brief Two bodies touching: link and object names as the planning scene names them.
struct ContactPair
{
  std::string a, b;
  bool touching() const { return !a.empty() || !b.empty(); }
};

/// \brief An IK answer: the joints, or why there are none (out of reach, in collision, joint limits).
struct IkAnswer
{
  std::optional<std::vector<double>> joints;
  std::string reason;
};

/// \brief What planning a run needs of the arm that runs it: IK of its TCP, a collision check of states along a
/// path against the scene as it is (other robots, objects; a held object attached), and forward kinematics. On a
/// running workspace the planning node's services (compute_ik, check_path, compute_fk: one round trip per
/// piece's check, not per state); in a benchmark vrrw_kinematics itself.
class ArmKinematics
{
public:
  virtual ~ArmKinematics() = default;
  /// \brief The joints nearest \a seed that put the TCP at \a tcp (world); with \a avoid_collisions only a
  /// state touching nothing.
  virtual IkAnswer ik(const CartesianPose& tcp, const std::vector<double>& seed, bool avoid_collisions) = 0;
  /// \brief Per state of \a path (the arm's joints), the first pair the arm touches there (none: not
  /// touching(); outside the joint limits: "joint limits" and the violation).
  virtual std::vector<ContactPair> checkPath(const std::vector<std::vector<double>>& path) = 0;
  /// \brief The TCP (world) at \a joints.
  virtual CartesianPose tcp(const std::vector<double>& joints) = 0;
};

/// \brief The cell as it is now, and the arm that is to do the skill.
struct SkillScene
{
  std::string robot;                    ///< the arm's robot name
  std::vector<std::string> arm_joints;  ///< its arm joints, base to tip
  std::vector<double> joints;           ///< where it stands
  std::vector<double> max_velocity;     ///< its joints' velocity limits (URDF), rad/s
  std::vector<double> max_acceleration; ///< its joints' acceleration limits (the scene's config), rad/s^2
  CartesianPose object;                 ///< the object now (world)
  std::optional<CartesianPose> place;   ///< the skill's place_on object now (world)
};

/// \brief One instruction ready to execute: a FollowJointTrajectory goal or a GripperCommand goal.
struct PlannedStep
{
  std::string instruction;
  bool gripper = false;
  vrrw_trajectory::JointTrajectory trajectory;  ///< arm: times from 0, positions and velocities
  bool cartesian = false;  ///< arm: the Cartesian DMP followed by IK (another arm, or the joint rollout collided)
  double gripper_position = 0.0;
  double gripper_effort = 0.0;
  /// arm: rad per joint the arm may end from the goal (the goal's goal_tolerance); 0: the controller's own
  double goal_tolerance = 0.0;
};

/// \brief Where the skill's keyframes put the TCP for a scene (world), per arm instruction.
std::map<std::string, CartesianPose> goalPoses(const Skill& skill, const SkillScene& scene,
                                               const CartesianPose& object_in_hand);

/// \brief Plans a skill's run on one arm: every instruction's goal from the keyframes and where things are
/// now, IK per arm (seeded with the taught joints on the taught arm, else with the previous goal), the taught
/// arm's joint DMPs rolled out between those goals, or for another arm the Cartesian DMPs rolled out between
/// the TCP goals and followed by IK, each piece checked for collisions state by state. A joint rollout that
/// collides is planned again along the Cartesian DMP (a joint rollout to moved goals bends the TCP's path, the
/// Cartesian one keeps its shape: the height a carry keeps above the table). A run is planned in two
/// parts: approach() up to the closed gripper, then, with the object held and attached in the planning scene,
/// carry() from where the arm and the object are then. Throws SkillRefusal naming the instruction and why
/// (no IK: out of reach or in collision; a collision on the way; a joint jump).
class SkillPlanner
{
public:
  SkillPlanner(const Skill& skill, ArmKinematics& arm);

  /// \brief True when the scene's arm is the taught one (the same robot and joints): joint DMPs apply.
  bool taughtArm(const SkillScene& scene) const;
  /// \brief Every goal by IK with the demonstrated hold (refuses an unreachable pose before anything moves),
  /// then near_pick, pick and close_gripper.
  std::vector<PlannedStep> approach(const SkillScene& scene);
  /// \brief back_to_near_pick, final (its goal puts the object where it came to rest in the demonstration, from how
  /// \a object_in_hand says it is held now) and open_gripper, from \a scene.joints.
  std::vector<PlannedStep> carry(const SkillScene& scene, const CartesianPose& object_in_hand);
  /// \brief The goals (joints) of the last plan, per instruction.
  const std::map<std::string, std::vector<double>>& goals() const { return goals_; }

  /// rad: a joint rollout after tau this close to its goal ends there (the controller's last segment closes it)
  static constexpr double kSettledWithin = 3e-3;
  /// Fraction of a joint's velocity and acceleration limits a rollout may reach before it is slowed down as a
  /// whole (tau scaled: velocities go with 1/tau, accelerations with 1/tau^2).
  static constexpr double kVelocityMargin = 0.9;
  /// rad: the largest change of any joint between two checked states of a piece.
  static constexpr double kCheckStep = 0.02;
  /// rad per joint: the set-down (final) ends with the object pressed onto what it is put on, and the arm may
  /// stop that far from its goal. The goal is computed from the hold before the lift; in the carry the object
  /// turns in the fingers (a 1.5 kg drill in the gripper's rated 235 N: 1-4 deg, from trial to trial), lands on
  /// an edge, and the support holds the hand back where a looser grip lets the object turn flat: wrist_1 ended
  /// 0.011-0.030 rad short in 12 of 20 trials, with the drill on the table; the controller's 0.01 aborted them.
  static constexpr double kSetDownTolerance = 0.05;

private:
  void solveGoals(const SkillScene& scene, const CartesianPose& object_in_hand, const std::vector<std::string>& names);
  vrrw_trajectory::JointTrajectory motion(const SkillInstruction& instruction, const SkillScene& scene,
                                          const std::vector<double>& start, const std::vector<double>& goal);
  vrrw_trajectory::JointTrajectory cartesianMotion(const SkillInstruction& instruction, const SkillScene& scene,
                                                   const std::vector<double>& start, const std::vector<double>& goal);
  void checkPiece(const std::string& instruction, const vrrw_trajectory::JointTrajectory& motion);
  PlannedStep armStep(const std::string& name, const SkillScene& scene, const std::vector<double>& from);
  PlannedStep gripperStep(const std::string& name) const;

  const Skill& skill_;
  ArmKinematics& arm_;
  std::map<std::string, std::vector<double>> goals_;
  std::map<std::string, CartesianPose> poses_;
};
}  // namespace vrrw_skills
