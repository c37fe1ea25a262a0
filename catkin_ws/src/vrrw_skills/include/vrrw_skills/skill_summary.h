#pragma once
#include <string>

#include <vrrw_skills/skill.h>

namespace vrrw_skills
{
/// \brief What `skill learn` prints: per instruction its demonstrated duration and the DMPs' (the pauses cut
/// out), the fit errors, the gripper's position and effort; the grasp relative to the object (position, and
/// its rotation as an angle about an axis). Lines end in '\n'.
std::string skillSummary(const Skill& skill);

/// \brief The summary's JSON line: skill (the path), instructions, joint_fit_rmse_rad, cartesian_fit_rmse_m,
/// cartesian_fit_rmse_deg (the largest over the arm instructions), per instruction its durations, the grasp
/// (grasp_position_m, grasp_angle_axis), demonstrations, and learn_seconds.
std::string skillJson(const Skill& skill, const std::string& path, double learn_seconds);
}  // namespace vrrw_skills
