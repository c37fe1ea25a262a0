#include "learn_command.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <sys/stat.h>

#include <vrrw_common/options.h>
#include <vrrw_demos/ros/demo_bag.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_learning.h>
#include <vrrw_skills/skill_summary.h>
#include <vrrw_skills/skill_yaml.h>

namespace vrrw_skills
{
int learnCommand(int argc, char** argv)
{
  const vrrw_common::Options options(argc, argv, 2, { "object", "robot", "place-on", "out" });
  if (options.positional().empty())
    throw vrrw_common::OptionError("missing BAG (usage: skill learn BAG [BAG...] --object NAME [--robot R] "
                                   "[--place-on NAME] --out SKILL.yaml)");
  LearnOptions learn;
  learn.object = options.text("object");
  learn.robot = options.text("robot", "");
  learn.place_on = options.text("place-on", "");
  const std::string out = options.text("out");
  struct stat info;
  if (::stat(out.c_str(), &info) == 0)
    throw SkillError(out + ": exists; not overwritten (remove it or choose another name)");
  const auto start = std::chrono::steady_clock::now();
  std::vector<vrrw_demos::Demonstration> demos;
  for (const std::string& bag : options.positional())
  {
    std::cout << "skill learn: reading " << bag << std::endl;
    demos.push_back(vrrw_demos::readDemonstration(
        bag, learn.robot.empty() ? std::vector<std::string>{} : std::vector<std::string>{ learn.robot }));
    demos.back().source = std::filesystem::absolute(bag).lexically_normal().string();
  }
  const Skill skill = learnSkill(demos, learn);
  saveSkill(skill, out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << skillSummary(skill) << "written: " << out << "\n" << skillJson(skill, out, seconds) << std::endl;
  return 0;
}
}  // namespace vrrw_skills
