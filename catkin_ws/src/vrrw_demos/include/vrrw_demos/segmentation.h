#pragma once
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>

namespace vrrw_demos
{
/// \brief Thresholds of the keyframe rule: the arm rests while its fastest joint is below still_speed
/// for at least min_still (debounce); a motion's ends are then moved outward while the speed is above
/// rest_speed, so a boundary lands where the motion really begins, not where it passes the threshold.
///
/// A person's demonstration is not a script's: the speed is the slope of the recorded positions over speed_window
/// (a held load's jitter and the drives' ripple, which the recorded velocities carry at up to 0.26 rad/s while
/// the arm stays within a millimetre, average out), rest_speed rises to twice the arm's own noise at rest, a
/// motion that moves no joint by min_motion is a twitch (a grip's jerk, a payload's sag) and no instruction,
/// and rests on the straight way into the grasp or out of it (within line_tolerance of the TCP's line) stay
/// inside pick and back_to_near_pick: a hesitant descent or lift is one instruction.
struct SegmentationOptions
{
  double still_speed = 0.05;     ///< rad/s (m/s)
  double rest_speed = 0.002;     ///< rad/s (m/s); at least twice the noise measured at rest
  double min_still = 0.2;        ///< s
  double speed_window = 0.1;     ///< s: the slope of the positions over this span is the speed
  double min_motion = 0.01;      ///< rad (m): a motion moving no joint more than this is a twitch
  double line_tolerance = 0.015; ///< m: rests within this of the TCP's straight way to (from) the grasp
  double gripper_speed = 0.02;   ///< rad/s (m/s) of the gripper's actuated joint: it moves above this
  double object_moved = 0.005;   ///< m: an object moved more than this between close and open is held
};

/// \brief The paper's pick-and-place instruction set (section III-C), in order; back_to_near_pick is optional.
constexpr const char* kSegmentNames[] = { "near_pick", "pick", "close_gripper", "back_to_near_pick", "final",
                                          "open_gripper" };

/// \brief One instruction: an arm motion (a FollowJointTrajectory goal) or a gripper action (GripperCommand).
struct Segment
{
  std::string name;
  double start = 0.0, end = 0.0;  ///< s from the demonstration's start
  bool gripper = false;
  double gripper_target = 0.0;    ///< gripper segments: the commanded (or reached) position
  std::string object;             ///< the object held (or picked / released)
};

struct Segmentation
{
  std::vector<Segment> segments;
  std::vector<std::string> warnings;  ///< why an instruction is missing
};

/// \brief Motion intervals [start, end] of the arm, by the keyframe rule (twitches left out).
std::vector<std::pair<double, double>> armMotions(const RobotTrack& track, const SegmentationOptions& options);

/// \brief Splits one robot's demonstration into the six pick-and-place instructions: gripper actions
/// from its gripper goals (else from the gripper joint's motion; the first action after the arm has moved
/// closes, the next opens), arm motions by the keyframe rule, the held object from the objects' motion.
/// With the TCP (the demonstration's metadata has the URDF and the robot's tcp_link), pick is every motion
/// on the straight way into the grasp and back_to_near_pick every motion on the straight way out of it;
/// without, pick is the last motion before the grasp and back_to_near_pick the first after it.
Segmentation segmentPickPlace(const RobotTrack& track, const Demonstration& demo,
                              const SegmentationOptions& options = {});

/// \brief The instruction \a name of \a track by segmentPickPlace; throws DemoError naming the demonstration's
/// source and listing the instructions found.
Segment findSegment(const Demonstration& demo, const RobotTrack& track, const std::string& name);

/// \brief The state at time t, linearly interpolated (clamped to the recorded span).
RobotState stateAt(const RobotTrack& track, double t);

/// \brief The states of [start, end] (inclusive, with the interpolated ends), times kept.
RobotTrack slice(const RobotTrack& track, double start, double end);
}  // namespace vrrw_demos
