#include "run_command.h"

#include <csignal>
#include <iostream>

#include <ros/ros.h>
#include <vrrw_common/options.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_common/ros/workspace_check.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/trial_outcome.h>
#include <vrrw_skills/skill_yaml.h>

#include <vrrw_skills/ros/skill_runner.h>

namespace vrrw_skills
{
namespace
{
void interruptArm(int)
{
  WorkspaceArm::interrupt();
}

/// Real mode moves a real arm: the operator says yes first (or gave --yes).
void confirmRealRun(const WorkspaceArm& arm, bool yes)
{
  if (arm.mode() != "real" || yes)
    return;
  std::cout << "skill run: this moves the REAL robot '" << arm.robot()
            << "' (each goal simulated first). Type yes to go on: " << std::flush;
  std::string answer;
  std::getline(std::cin, answer);
  if (answer != "yes")
    throw SkillError("--yes: not confirmed; nothing sent");
}

/// The outcome a person looks for: where the object came to rest, against where the skill leaves it (a skill that
/// places onto a support leaves it relative to that support: its world place is not judged here).
void sayWhereItRests(WorkspaceArm& arm, const Skill& skill, const std::string& object)
{
  ros::Duration(0.5).sleep();  // (simulated time) the released object comes to rest
  const auto rests = arm.pose(object);
  if (!rests)
    return void(std::printf("skill run: %s is not in tf: where it rests is unknown\n", object.c_str()));
  const Eigen::Isometry3d end = toIsometry(*rests);
  const Eigen::Vector3d at = end.translation();
  std::printf("skill run: %s rests at (%.3f, %.3f, %.3f) m", object.c_str(), at.x(), at.y(), at.z());
  if (skill.place_on.empty())
  {
    const Eigen::Isometry3d taught = toIsometry(skill.object_end);  // as skill evaluate judges a place
    std::printf(", %.1f mm and %.1f deg from where the skill leaves it", 1000.0 * planarDistance(end, taught),
                yawDifferenceDeg(end, taught));
  }
  std::printf("\n");
  std::fflush(stdout);
}
}  // namespace

int runCommand(int argc, char** argv)
{
  const vrrw_common::Options options(argc, argv, 2, { "robot", "object" }, { "yes" });
  options.expectPositional({ "SKILL.yaml" });
  const Skill skill = loadSkill(options.positional().front());
  const std::string robot = options.text("robot", skill.robot);
  int ros_argc = 1;
  ros::init(ros_argc, argv, "skill_run", ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  const vrrw_common::ToolNode node_registration;
  const std::string ns = "/" + robot + "/";
  vrrw_common::checkWorkspace({ robot,
                                { ns + "arm_controller/follow_joint_trajectory",
                                  ns + "gripper_controller/gripper_cmd" },
                                { ns + "compute_ik", ns + "check_path", ns + "compute_fk", ns + "attach_object" } });
  std::signal(SIGINT, interruptArm);
  std::signal(SIGTERM, interruptArm);
  ros::NodeHandle node;
  ros::AsyncSpinner spinner(2);
  spinner.start();
  vrrw_common::PersistentServices services;
  WorkspaceArm arm(node, robot, services);
  arm.waitUntilReady(10.0);
  confirmRealRun(arm, options.flag("yes"));
  ArmServices kinematics(services, robot, arm.armJoints());
  SkillRunner runner(skill, arm, kinematics, options.text("object", ""));
  auto print = [](const std::string& line) { std::cout << "skill run: " << line << std::endl; };
  try
  {
    const RunReport report = runner.run(print);
    std::printf("skill run: done in %.2f s (planning %.0f ms)\n", report.cycle_seconds, 1000.0 * report.planning_seconds);
    sayWhereItRests(arm, skill, options.text("object", skill.object));
  }
  catch (const SkillRefusal& e)
  {
    std::cerr << "skill run: " << e.what() << std::endl;
    spinner.stop();
    return 1;
  }
  spinner.stop();
  return 0;
}
}  // namespace vrrw_skills
