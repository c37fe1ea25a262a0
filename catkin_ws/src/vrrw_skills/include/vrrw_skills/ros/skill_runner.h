#pragma once
// A skill carried out on the running workspace: goals from where the object is now, planned (SkillPlanner over
// the planning node's services), executed through the arm's controllers.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <vrrw_skills/skill.h>
#include <vrrw_skills/skill_plan.h>

#include <vrrw_skills/ros/arm_services.h>
#include <vrrw_skills/ros/workspace_arm.h>

namespace vrrw_skills
{
/// \brief What one run took.
struct RunReport
{
  double planning_seconds = 0.0;  ///< wall: IK, rollouts and collision checks of both parts
  double cycle_seconds = 0.0;     ///< simulated: from the first goal sent to the gripper open
  std::vector<std::pair<std::string, double>> instruction_seconds;  ///< simulated, per instruction
};

class SkillRunner
{
public:
  /// \brief \a object: the scene object to pick (empty: the skill's); the arm may be another than the taught one.
  SkillRunner(const Skill& skill, WorkspaceArm& arm, ArmServices& services, std::string object = "");

  using Progress = std::function<void(const std::string&)>;
  /// \brief Checks the start (the object in tf, the arm at rest: SkillError otherwise), plans and executes every
  /// instruction, printing a line per instruction through \a progress and calling \a done (when given) with each
  /// instruction's name once it ended. Throws SkillRefusal naming the instruction and why (before anything moved
  /// when a goal has no IK).
  RunReport run(const Progress& progress, const Progress& done = {});

  /// rad/s: an arm faster than this is moving; a run does not start then.
  static constexpr double kRestSpeed = 0.01;

private:
  SkillScene scene() const;
  void execute(const std::vector<PlannedStep>& steps, RunReport& report, const Progress& progress,
               const Progress& done);

  const Skill& skill_;
  WorkspaceArm& arm_;
  ArmServices& services_;
  std::string object_;
};
}  // namespace vrrw_skills
