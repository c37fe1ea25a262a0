#pragma once
// `skill learn BAG [BAG...] --object NAME [--robot R] [--place-on NAME] --out SKILL.yaml`.
namespace vrrw_skills
{
/// \brief Reads the bags (vrrw_demos' reader), learns, writes the skill, prints the summary and the JSON
/// line. Returns the exit code; bad input throws (SkillError, DemoError, vrrw_common::OptionError).
int learnCommand(int argc, char** argv);
}  // namespace vrrw_skills
