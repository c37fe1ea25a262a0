#pragma once
#include <string>

#include <vrrw_skills/skill.h>

namespace vrrw_skills
{
/// Skill files are YAML (format "vrrw_skills/1"): the taught robot (name, arm joints, TCP link, gripper joint,
/// home), the object (its start and end in the world, where it sat in the hand when released), the place
/// object, per instruction its duration, keyframes (frame, position, quaternion x y z w), joints at both ends,
/// fit errors, the joint DMP and the Cartesian DMP (vrrw_dmp's fields), or the gripper's position, reached
/// position and effort; the sources (bag, scene, start stamp, segments) and when and by what it was written.
/// Doubles have 17 significant digits: a loaded skill saves to the same bytes, and rolls out the same.

/// \brief The skill as YAML text.
std::string toYaml(const Skill& skill);
/// \brief Parses a skill; \a source names it in errors. Throws SkillError `SOURCE: field: reason` (a file cut
/// short, another format version, a quaternion whose norm is not 1, a keyframe in an unknown frame, ...).
Skill fromYaml(const std::string& text, const std::string& source);

/// \brief Writes the file whole or not at all; never over an existing file (SkillError naming it).
void saveSkill(const Skill& skill, const std::string& path);
/// \brief Reads a skill file; throws SkillError naming the path and the field.
Skill loadSkill(const std::string& path);
}  // namespace vrrw_skills
