#pragma once
#include <vrrw_physics/drive_mode.h>

#include <string>
#include <vector>

#include <vrrw_scene/scene.h>

namespace vrrw_physics
{
class ArticulatedRobot;
struct SimJoint;

/// \brief The joint drives of one robot as they are commanded: the mode and its gains from the robot's
/// config (gripper joints keep their rigid gains in every mode), custom gains, targets with a force limit,
/// and a hold when targets stop arriving.
///
/// Every change of mode (and custom gains, which switch to Custom) sets the arm's targets to where the
/// arm is, at rest, so leaving compliant mode holds the pose instead of pulling back to a stale target.
class RobotDrives
{
public:
  /// \brief The drives of `robot` (built from `spec`) in `mode`; targets are left as they are. Target
  /// velocities beyond `max_speed` (rad/s or m/s: the world's guard limit) are refused.
  RobotDrives(const vrrw_scene::Robot& spec, ArticulatedRobot& robot, DriveMode mode, double max_speed);

  /// s a streamed target is carried along its velocity without a newer one (first-order hold).
  static constexpr double kTargetExtrapolation = 0.05;

  /// \brief Targets by prefixed joint name at simulated time `now`. velocities empty: 0. efforts empty or 0:
  /// the configured force limit; efforts > 0 lower it (N m or N, capped at the configured limit) until the
  /// next targets for that joint. Throws InputError naming the joint and the range; nothing is applied then.
  void setTargets(const std::vector<std::string>& joints, const std::vector<double>& positions,
                  const std::vector<double>& velocities, const std::vector<double>& efforts, double now);
  /// \brief The same for drives named by index (drives()), as a controller in the stepping thread sets them
  /// every step without looking names up. Throws InputError naming the joint and the range.
  void setTargetsByIndex(const std::vector<std::size_t>& drives, const std::vector<double>& positions,
                  const std::vector<double>& velocities, const std::vector<double>& efforts, double now);
  /// \brief The drive of each joint (prefixed names of driven joints). Throws InputError naming a joint that is
  /// unknown, a mimic joint or named twice.
  std::vector<std::size_t> drives(const std::vector<std::string>& joints) const;
  /// \brief After `timeout` s without targets (0: never) every target velocity becomes 0 and every target
  /// position stays: the robot comes to rest at its last commanded pose. A stale velocity means nothing without
  /// the targets that should follow it, while a position target is a whole command (a script's one-shot target
  /// must still be reached, a gripper must keep squeezing what it holds). true at the step it happens.
  bool holdIfStale(double now, double timeout);
  /// \brief Before a step at `now`: each streamed target position moves on along its target velocity from
  /// where and when it arrived, for up to kTargetExtrapolation. A controller's targets arrive asynchronously;
  /// a late one (the controller descheduled, or physics catching up with the wall clock) would otherwise
  /// leave the drive pulling towards where the arm should have been, v * delay behind.
  void advance(double now);
  /// \brief Streamed targets end here (their positions and velocities stay as they are): a restored state.
  void endStream() { streamed_.assign(streamed_.size(), Streamed()); }

  void setMode(DriveMode mode);
  DriveMode mode() const { return mode_; }
  /// \brief Custom gains of the listed joints, or, with `joints` empty, of the arm joints in order;
  /// max_force empty keeps the limits. Throws InputError naming the joint and the range.
  void setGains(const std::vector<std::string>& joints, const std::vector<double>& stiffness,
                const std::vector<double>& damping, const std::vector<double>& max_force);
  /// \brief Gains in effect for a joint. Throws InputError.
  DriveGains gains(const std::string& joint) const;
  /// \brief Back to `mode` with the config's gains and force limits, nothing streaming.
  void reset(DriveMode mode);

private:
  /// Index in robot.drives() of a driven joint; throws InputError naming `what` otherwise.
  std::size_t drive(const std::string& joint, const std::string& what) const;
  /// Throws InputError naming the joint, the value and its range (a target found out of range).
  void checkTarget(const SimJoint& sim, double position, double velocity, double effort) const;
  void applyMode();
  void holdArm();

  std::string name_;
  ArticulatedRobot& robot_;
  DriveMode mode_;
  double max_speed_;
  std::vector<std::size_t> joint_of_drive_;
  std::vector<bool> arm_;                        ///< per drive
  std::vector<vrrw_scene::JointGains> config_;   ///< per drive
  std::vector<double> force_limit_;              ///< per drive: of the mode or the custom gains
  std::vector<std::string> arm_joints_;
  double last_targets_ = 0.0;
  bool streaming_ = false;
  struct Streamed
  {
    bool active = false;
    double position = 0.0, velocity = 0.0, time = 0.0;  ///< as the last targets gave it, at their arrival
  };
  std::vector<Streamed> streamed_;  ///< per drive
};
}  // namespace vrrw_physics
