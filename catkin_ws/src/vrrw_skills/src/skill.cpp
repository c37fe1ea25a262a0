#include <vrrw_skills/skill.h>

#include <vrrw_skills/skill_error.h>

namespace vrrw_skills
{
std::string toString(Frame frame)
{
  switch (frame)
  {
    case Frame::world:
      return "world";
    case Frame::object:
      return "object";
    case Frame::place:
      return "place";
  }
  return "world";
}

Frame frameFromString(const std::string& text, const std::string& field)
{
  if (text == "world")
    return Frame::world;
  if (text == "object")
    return Frame::object;
  if (text == "place")
    return Frame::place;
  throw SkillError(field + ": '" + text + "' is not world, object or place");
}

const SkillInstruction* Skill::instruction(const std::string& name) const
{
  for (const SkillInstruction& instruction : instructions)
    if (instruction.name == name)
      return &instruction;
  return nullptr;
}

const Keyframe& Skill::grasp() const
{
  const SkillInstruction* pick = instruction("pick");
  if (!pick)
    throw SkillError("skill: instructions: no pick, so no grasp");
  return pick->end;
}

std::vector<const SkillInstruction*> Skill::armInstructions() const
{
  std::vector<const SkillInstruction*> arm;
  for (const SkillInstruction& instruction : instructions)
    if (!instruction.gripper)
      arm.push_back(&instruction);
  return arm;
}
}  // namespace vrrw_skills
