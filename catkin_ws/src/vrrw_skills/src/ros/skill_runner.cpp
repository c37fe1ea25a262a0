#include <vrrw_skills/ros/skill_runner.h>

#include <chrono>
#include <cstdio>

#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_skills/skill_plan.h>

namespace vrrw_skills
{
namespace
{
std::string format(const char* pattern, double a, double b = 0.0)
{
  char text[128];
  std::snprintf(text, sizeof(text), pattern, a, b);
  return text;
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

SkillRunner::SkillRunner(const Skill& skill, WorkspaceArm& arm, ArmServices& services, std::string object)
  : skill_(skill), arm_(arm), services_(services), object_(object.empty() ? skill.object : std::move(object))
{
}

SkillScene SkillRunner::scene() const
{
  SkillScene scene;
  scene.robot = arm_.robot();
  scene.arm_joints = arm_.armJoints();
  scene.joints = arm_.joints();
  scene.max_velocity = arm_.maxVelocities();
  scene.max_acceleration = arm_.maxAccelerations();
  const auto object = arm_.pose(object_);
  if (!object)
    throw SkillError("--object " + object_ + ": not in tf (is it an object of the running scene?)");
  scene.object = *object;
  if (!skill_.place_on.empty())
  {
    scene.place = arm_.pose(skill_.place_on);
    if (!scene.place)
      throw SkillError("place_on " + skill_.place_on + ": not in tf (the skill places onto it)");
  }
  return scene;
}

void SkillRunner::execute(const std::vector<PlannedStep>& steps, RunReport& report, const Progress& progress,
                          const Progress& done)
{
  for (const PlannedStep& step : steps)
  {
    const ros::Time start = arm_.now();
    if (step.gripper)
    {
      progress(step.instruction + ": gripper to " + format("%.3f", step.gripper_position) +
               format(", effort %.0f N", step.gripper_effort));
      arm_.grip(step.instruction, step.gripper_position, step.gripper_effort);
    }
    else
    {
      progress(step.instruction + ": " + format("%.2f s of motion, %.0f points", step.trajectory.duration(),
                                                double(step.trajectory.points.size())) +
               (step.cartesian ? " (the Cartesian DMP by IK)" : ""));
      arm_.execute(step.instruction, step.trajectory, step.goal_tolerance);
    }
    report.instruction_seconds.push_back({ step.instruction, (arm_.now() - start).toSec() });
    if (done)
      done(step.instruction);
  }
}

RunReport SkillRunner::run(const Progress& progress, const Progress& done)
{
  RunReport report;
  if (arm_.speed() > kRestSpeed)
    throw SkillError("--robot " + arm_.robot() + ": the arm is moving (" + format("%.3f", arm_.speed()) +
                     " rad/s): a skill starts from rest");
  SkillScene here = scene();
  SkillPlanner planner(skill_, services_);
  progress(planner.taughtArm(here) ? "the taught arm: joint DMPs between IK goals"
                                   : "arm " + arm_.robot() + " (taught: " + skill_.robot +
                                         "): Cartesian DMPs followed by IK");
  auto start = std::chrono::steady_clock::now();
  const auto approach = planner.approach(here);
  report.planning_seconds += secondsSince(start);
  progress(format("planned the approach in %.0f ms", 1000.0 * report.planning_seconds));
  const ros::Time cycle_start = arm_.now();
  execute(approach, report, progress, done);
  // holding it: the planning scene carries the object with the hand from here
  services_.attach(object_, true);
  try
  {
    here.joints = arm_.joints();
    const auto tcp = arm_.pose(arm_.tcpLink());
    const auto object = arm_.pose(object_);
    if (!tcp || !object)
      throw SkillRefusal("back_to_near_pick: the TCP or the object left tf");
    const CartesianPose in_hand = relativeTo(*tcp, *object);
    start = std::chrono::steady_clock::now();
    const auto carry = planner.carry(here, in_hand);
    const double carry_seconds = secondsSince(start);
    report.planning_seconds += carry_seconds;
    progress(format("planned the carry in %.0f ms", 1000.0 * carry_seconds));
    execute(carry, report, progress, done);
  }
  catch (...)
  {
    services_.attach(object_, false);
    throw;
  }
  services_.attach(object_, false);
  report.cycle_seconds = (arm_.now() - cycle_start).toSec();
  return report;
}
}  // namespace vrrw_skills
