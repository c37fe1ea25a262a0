#pragma once
// `skill run SKILL.yaml [--robot R] [--object NAME] [--yes]` on the workspace at $ROS_MASTER_URI.
namespace vrrw_skills
{
/// \brief Loads the skill, checks the workspace (within 2 s), runs it. Returns the exit code; bad input throws.
int runCommand(int argc, char** argv);
}  // namespace vrrw_skills
