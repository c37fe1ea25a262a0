#pragma once
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>
#include <vrrw_demos/segmentation.h>
#include <vrrw_dmp/dmp_parameters.h>
#include <vrrw_skills/skill.h>

namespace vrrw_skills
{
/// \brief The DMP parameters a skill learns with: 30 basis functions, `auto` scaling, and joints (axes)
/// that move less than 2 cm (rad) scaled by their range (the demo's generalization measured them).
vrrw_dmp::DmpParameters skillDmpParameters();

/// \brief What `skill learn` is asked.
struct LearnOptions
{
  std::string object;    ///< the object picked (must be in the bags' tf and move while held)
  std::string robot;     ///< the taught robot; empty: the bags' only robot
  std::string place_on;  ///< empty: the place is in the world; else the object it is put on
  vrrw_dmp::DmpParameters parameters = skillDmpParameters();
  vrrw_demos::SegmentationOptions segmentation;
  double sample_period = 0.01;  ///< s: each motion is learned resampled at this period, its pauses cut out
};

/// \brief Learns a skill from demonstrations of the same task (read by vrrw_demos::readDemonstration):
/// each is segmented into the pick-and-place instructions (the keyframe rule, no annotations needed),
/// the TCP found by the bag's own URDF, the object's pose from the recorded tf. Keyframes: approach (near_pick's
/// end), grasp (pick's end) and retreat (back_to_near_pick's end) relative to the object at the start of the
/// demonstration; the place (final's end) in the world or relative to \a place_on. The keyframes and the
/// gripper's positions and efforts are the mean over the demonstrations; the DMPs are the first one's.
/// Throws SkillError `BAG: <field>: <reason>` for a demonstration that does not show the task (no such object
/// or robot, no gripper closing or opening, an object that never moved, bags of different robots).
Skill learnSkill(const std::vector<vrrw_demos::Demonstration>& demos, const LearnOptions& options);

/// \brief A track's motion from \a start to \a end (s) as the DMPs learn it: the arm's pauses inside longer than
/// 0.5 s cut to 0.5 s (a person's hesitation goes, a stop that is part of the motion stays), resampled every
/// \a period from 0. Joint names from the track.
vrrw_trajectory::JointTrajectory motionWithoutPauses(const vrrw_demos::RobotTrack& track, double start, double end,
                                                     double period, const vrrw_demos::SegmentationOptions& options);
}  // namespace vrrw_skills
