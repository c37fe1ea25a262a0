#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_skills
{
/// \brief Bad skill input (a bag, a skill file, an option, a pose); what() is one line
/// `<what>: <field>: <reason>` naming the file or option.
class SkillError : public std::invalid_argument
{
public:
  explicit SkillError(const std::string& what) : std::invalid_argument(what) {}
};

/// \brief A skill that cannot be carried out where things are now (no IK, a collision, an action that
/// failed); what() names the instruction and the reason.
class SkillRefusal : public std::runtime_error
{
public:
  explicit SkillRefusal(const std::string& what) : std::runtime_error(what) {}
};
}  // namespace vrrw_skills
