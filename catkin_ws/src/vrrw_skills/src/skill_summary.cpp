#include <vrrw_skills/skill_summary.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <vrrw_skills/poses.h>

#include "json_text.h"

namespace vrrw_skills
{
namespace
{
std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0, double d = 0.0)
{
  char text[256];
  std::snprintf(text, sizeof(text), pattern, a, b, c, d);
  return text;
}

/// The DMPs' duration: the demonstration's motion with its pauses cut out.
double moving(const SkillInstruction& instruction)
{
  return instruction.joint_dmp ? instruction.joint_dmp->demoDuration() : instruction.duration;
}

std::string frameName(const Skill& skill, Frame frame)
{
  switch (frame)
  {
    case Frame::object:
      return skill.object;
    case Frame::place:
      return skill.place_on;
    case Frame::world:
      break;
  }
  return "world";
}
}  // namespace

std::string skillSummary(const Skill& skill)
{
  std::string out = "skill: robot " + skill.robot + " picks '" + skill.object + "'" +
                    (skill.place_on.empty() ? " and places it in the world" : " and places it on '" + skill.place_on + "'") +
                    ", from " + std::to_string(skill.sources.size()) + " demonstration" +
                    (skill.sources.size() == 1 ? "" : "s") + "\n";
  out += "  instruction         shown s  DMP s  joint fit rad  TCP fit mm / deg  ends in\n";
  for (const SkillInstruction& instruction : skill.instructions)
  {
    char line[256];
    if (instruction.gripper)
      std::snprintf(line, sizeof(line), "  %-18s %7.2f         to %.3f (reached %.3f), effort %.0f N\n",
                    instruction.name.c_str(), instruction.duration, instruction.gripper_position,
                    instruction.gripper_reached, instruction.gripper_effort);
    else
      std::snprintf(line, sizeof(line), "  %-18s %7.2f %6.2f  %13.2e  %7.2f / %5.3f  %s frame\n", instruction.name.c_str(),
                    instruction.duration, moving(instruction), instruction.joint_fit_rmse,
                    instruction.cartesian_fit_rmse * 1000.0, instruction.cartesian_fit_rmse_deg,
                    frameName(skill, instruction.end.frame).c_str());
    out += line;
  }
  const Keyframe& grasp = skill.grasp();
  const Eigen::AngleAxisd rotation(grasp.pose.orientation);
  out += "  grasp in '" + skill.object + "' frame: " +
         format("(%.4f, %.4f, %.4f) m, ", grasp.pose.position.x(), grasp.pose.position.y(), grasp.pose.position.z()) +
         format("turned %.2f deg about (%.3f, %.3f, %.3f)\n", rotation.angle() * 180.0 / M_PI, rotation.axis().x(),
                rotation.axis().y(), rotation.axis().z());
  return out;
}

std::string skillJson(const Skill& skill, const std::string& path, double learn_seconds)
{
  double joint = 0.0, position = 0.0, angle = 0.0;
  std::string names, durations;
  for (const SkillInstruction& instruction : skill.instructions)
  {
    names += (names.empty() ? "" : ",") + jsonString(instruction.name);
    durations += std::string(durations.empty() ? "" : ",") + jsonString(instruction.name) + ":" +
                 format("{\"shown_s\":%.4f,\"dmp_s\":%.4f}", instruction.duration, moving(instruction));
    joint = std::max(joint, instruction.joint_fit_rmse);
    position = std::max(position, instruction.cartesian_fit_rmse);
    angle = std::max(angle, instruction.cartesian_fit_rmse_deg);
  }
  const Keyframe& grasp = skill.grasp();
  const Eigen::AngleAxisd rotation(grasp.pose.orientation);
  return "{\"skill\":" + jsonString(path) + ",\"robot\":" + jsonString(skill.robot) + ",\"object\":" +
         jsonString(skill.object) + ",\"instructions\":[" + names + "],\"durations\":{" + durations + "}" +
         format(",\"joint_fit_rmse_rad\":%.6g,\"cartesian_fit_rmse_m\":%.6g,\"cartesian_fit_rmse_deg\":%.6g", joint,
                position, angle) +
         format(",\"grasp_position_m\":[%.6f,%.6f,%.6f]", grasp.pose.position.x(), grasp.pose.position.y(),
                grasp.pose.position.z()) +
         format(",\"grasp_angle_axis\":[%.6f,%.6f,%.6f,%.6f]", rotation.angle(), rotation.axis().x(),
                rotation.axis().y(), rotation.axis().z()) +
         ",\"demonstrations\":" + std::to_string(skill.sources.size()) +
         format(",\"learn_seconds\":%.3f}", learn_seconds);
}
}  // namespace vrrw_skills
