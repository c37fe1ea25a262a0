// vrrw_skill: the `./vrrw skill` tool.
//   learn BAG [BAG...] --object NAME [--robot R] [--place-on NAME] --out SKILL.yaml
//   run SKILL.yaml [--robot R] [--object NAME] [--yes]
//   evaluate SKILL.yaml --scene SCENE [--robot R] [--object NAME] [--trials N] [--seed S]
//            [--spread DX,DY,DYAW_DEG] [--out DIR] [--rtf max|N]
// Exit codes: 0 done, 1 failed while running (a refusal, a failed goal), 2 bad input (one line on stderr).
#include <iostream>
#include <string>

#include <vrrw_common/options.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_skills/skill_error.h>

#include "../src/ros/evaluate_command.h"
#include "../src/ros/learn_command.h"
#include "../src/ros/run_command.h"

namespace
{
const char* const kUsage =
    "usage: ./vrrw skill learn BAG [BAG...] --object NAME [--robot R] [--place-on NAME] --out SKILL.yaml\n"
    "       ./vrrw skill run SKILL.yaml [--robot R] [--object NAME] [--yes]\n"
    "       ./vrrw skill evaluate SKILL.yaml --scene SCENE [--robot R] [--object NAME] [--trials N] [--seed S]\n"
    "                             [--spread DX,DY,DYAW_DEG] [--out DIR] [--rtf max|N]\n";
}  // namespace

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  try
  {
    if (command == "learn")
      return vrrw_skills::learnCommand(argc, argv);
    if (command == "run")
      return vrrw_skills::runCommand(argc, argv);
    if (command == "evaluate")
      return vrrw_skills::evaluateCommand(argc, argv);
    if (command == "help" || command == "--help" || command == "-h")
      return std::cout << kUsage, 0;
    std::cerr << "skill: unknown command '" << command << "'\n" << kUsage;
    return 2;
  }
  catch (const vrrw_common::WorkspaceError& e)  // no workspace runs: a failure to run, as in every tool
  {
    std::cerr << "skill " << command << ": " << e.what() << "\n";
    return 1;
  }
  catch (const vrrw_common::OptionError& e)
  {
    std::cerr << "skill " << command << ": " << e.what() << "\n";
    return 2;
  }
  catch (const vrrw_skills::SkillError& e)
  {
    std::cerr << "skill " << command << ": " << e.what() << "\n";
    return 2;
  }
  catch (const vrrw_demos::DemoError& e)
  {
    std::cerr << "skill " << command << ": " << e.what() << "\n";
    return 2;
  }
  catch (const std::exception& e)
  {
    std::cerr << "skill " << command << ": " << e.what() << "\n";
    return 1;
  }
}
