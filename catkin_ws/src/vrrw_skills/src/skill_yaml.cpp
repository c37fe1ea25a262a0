#include <vrrw_skills/skill_yaml.h>

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include <vrrw_dmp/dmp_error.h>
#include <vrrw_dmp/dmp_yaml.h>
#include <vrrw_dmp/yaml_fields.h>
#include <vrrw_skills/skill_error.h>
#include <vrrw_trajectory/trajectory_error.h>
#include <vrrw_trajectory/whole_file.h>

namespace vrrw_skills
{
namespace
{
/// A skill file bigger than this is refused before parsing (a skill of 6 instructions is about 60 KB).
constexpr std::streamoff kMaxFileBytes = 16 * 1024 * 1024;

using vrrw_dmp::emitNumbers;

void pose(YAML::Emitter& out, const std::string& key, const CartesianPose& value)
{
  const Eigen::Quaterniond& q = value.orientation;
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "position" << YAML::Value;
  emitNumbers(out, { value.position.x(), value.position.y(), value.position.z() });
  out << YAML::Key << "orientation" << YAML::Value;
  emitNumbers(out, { q.x(), q.y(), q.z(), q.w() });
  out << YAML::EndMap;
}

void keyframe(YAML::Emitter& out, const std::string& key, const Keyframe& value)
{
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "frame" << YAML::Value << toString(value.frame);
  const Eigen::Quaterniond& q = value.pose.orientation;
  out << YAML::Key << "position" << YAML::Value;
  emitNumbers(out, { value.pose.position.x(), value.pose.position.y(), value.pose.position.z() });
  out << YAML::Key << "orientation" << YAML::Value;
  emitNumbers(out, { q.x(), q.y(), q.z(), q.w() });
  out << YAML::EndMap;
}

void instruction(YAML::Emitter& out, const SkillInstruction& value)
{
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << value.name;
  out << YAML::Key << "kind" << YAML::Value << (value.gripper ? "gripper" : "arm");
  out << YAML::Key << "duration" << YAML::Value << value.duration;
  if (value.gripper)
  {
    out << YAML::Key << "position" << YAML::Value << value.gripper_position;
    out << YAML::Key << "reached" << YAML::Value << value.gripper_reached;
    out << YAML::Key << "effort" << YAML::Value << value.gripper_effort;
    out << YAML::EndMap;
    return;
  }
  keyframe(out, "start", value.start);
  keyframe(out, "end", value.end);
  out << YAML::Key << "joints_start" << YAML::Value;
  emitNumbers(out, value.joints_start);
  out << YAML::Key << "joints_end" << YAML::Value;
  emitNumbers(out, value.joints_end);
  out << YAML::Key << "fit" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "joint_rmse_rad" << YAML::Value << value.joint_fit_rmse;
  out << YAML::Key << "cartesian_rmse_m" << YAML::Value << value.cartesian_fit_rmse;
  out << YAML::Key << "cartesian_rmse_deg" << YAML::Value << value.cartesian_fit_rmse_deg;
  out << YAML::EndMap;
  out << YAML::Key << "joint_dmp" << YAML::Value << YAML::BeginMap;
  vrrw_dmp::emitDmpFields(out, *value.joint_dmp);
  out << YAML::EndMap;
  out << YAML::Key << "cartesian_dmp" << YAML::Value << YAML::BeginMap;
  vrrw_dmp::emitCartesianDmpFields(out, *value.cartesian_dmp);
  out << YAML::EndMap;
  out << YAML::EndMap;
}

void source(YAML::Emitter& out, const SkillSource& value)
{
  out << YAML::BeginMap;
  out << YAML::Key << "bag" << YAML::Value << value.bag;
  out << YAML::Key << "scene" << YAML::Value << value.scene;
  out << YAML::Key << "vrrw_version" << YAML::Value << value.vrrw_version;
  out << YAML::Key << "start_stamp" << YAML::Value << value.start_stamp;
  out << YAML::Key << "segments" << YAML::Value << YAML::BeginSeq;
  for (const SourceSegment& segment : value.segments)
  {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << segment.name;
    out << YAML::Key << "start" << YAML::Value << segment.start << YAML::Key << "end" << YAML::Value << segment.end;
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
}

/// A skill file's fields (vrrw_dmp::YamlFields, its top level named "skill"), its poses and keyframes; errors
/// `SOURCE: path.to.field: reason` as DmpError, a SkillError at fromYaml.
class Reader : public vrrw_dmp::YamlFields
{
public:
  explicit Reader(std::string source) : YamlFields(std::move(source), "skill") {}

  CartesianPose pose(const YAML::Node& node, const std::string& key, const std::string& path) const
  {
    const YAML::Node value = child(node, key, path);
    return poseIn(value, path + key + ".");
  }

  CartesianPose poseIn(const YAML::Node& value, const std::string& path) const
  {
    const auto p = numbers(value, "position", path, 3);
    const auto q = numbers(value, "orientation", path, 4);
    const Eigen::Quaterniond orientation(q[3], q[0], q[1], q[2]);
    if (std::abs(orientation.norm() - 1.0) > 1e-9)
    {
      char norm[32];
      std::snprintf(norm, sizeof(norm), "%.9g", orientation.norm());
      fail(path + "orientation", std::string("norm ") + norm + " is not 1 (a unit quaternion x, y, z, w is needed)");
    }
    return { Eigen::Vector3d(p[0], p[1], p[2]), orientation };
  }

  Keyframe keyframe(const YAML::Node& node, const std::string& key, const std::string& path) const
  {
    const YAML::Node value = child(node, key, path);
    const std::string at = path + key + ".";
    return { frameFromString(scalar<std::string>(value, "frame", at), source() + ": " + at + "frame"),
             poseIn(value, at) };
  }
};

SkillInstruction readInstruction(const YAML::Node& node, const Reader& read, const std::string& at,
                                 std::size_t joints)
{
  SkillInstruction out;
  out.name = read.scalar<std::string>(node, "name", at);
  const auto kind = read.scalar<std::string>(node, "kind", at);
  if (kind != "arm" && kind != "gripper")
    read.fail(at + "kind", "'" + kind + "' is not arm or gripper");
  out.gripper = kind == "gripper";
  out.duration = read.scalar<double>(node, "duration", at);
  if (out.gripper)
  {
    out.gripper_position = read.scalar<double>(node, "position", at);
    out.gripper_reached = read.scalar<double>(node, "reached", at);
    out.gripper_effort = read.scalar<double>(node, "effort", at);
    return out;
  }
  out.start = read.keyframe(node, "start", at);
  out.end = read.keyframe(node, "end", at);
  out.joints_start = read.numbers(node, "joints_start", at, joints);
  out.joints_end = read.numbers(node, "joints_end", at, joints);
  const YAML::Node fit = read.child(node, "fit", at);
  out.joint_fit_rmse = read.scalar<double>(fit, "joint_rmse_rad", at + "fit.");
  out.cartesian_fit_rmse = read.scalar<double>(fit, "cartesian_rmse_m", at + "fit.");
  out.cartesian_fit_rmse_deg = read.scalar<double>(fit, "cartesian_rmse_deg", at + "fit.");
  try
  {
    out.joint_dmp = vrrw_dmp::parseDmpFields(read.child(node, "joint_dmp", at), read.source(), at + "joint_dmp.");
    out.cartesian_dmp =
        vrrw_dmp::parseCartesianDmpFields(read.child(node, "cartesian_dmp", at), read.source(), at + "cartesian_dmp.");
  }
  catch (const vrrw_dmp::DmpError& e)
  {
    throw SkillError(e.what());
  }
  if (out.joint_dmp->dofs() != joints)
    read.fail(at + "joint_dmp.joints", std::to_string(out.joint_dmp->dofs()) + " joints, the robot has " +
                                           std::to_string(joints));
  return out;
}

SkillSource readSource(const YAML::Node& node, const Reader& read, const std::string& at)
{
  SkillSource out;
  out.bag = read.scalar<std::string>(node, "bag", at);
  out.scene = read.scalar<std::string>(node, "scene", at);
  out.vrrw_version = read.scalar<std::string>(node, "vrrw_version", at);
  out.start_stamp = read.scalar<double>(node, "start_stamp", at);
  const YAML::Node segments = read.child(node, "segments", at);
  if (!segments.IsSequence())
    read.fail(at + "segments", "expected a list");
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    const std::string path = at + "segments[" + std::to_string(i) + "].";
    out.segments.push_back({ read.scalar<std::string>(segments[i], "name", path),
                             read.scalar<double>(segments[i], "start", path),
                             read.scalar<double>(segments[i], "end", path) });
  }
  return out;
}

Skill parse(const YAML::Node& root, const Reader& read)
{
  Skill skill;
  const auto format = read.scalar<std::string>(root, "format", "");
  if (format != Skill::kFormat)
    read.fail("format", "'" + format + "' is not '" + Skill::kFormat + "' (a skill of another version)");
  const YAML::Node robot = read.child(root, "robot", "");
  skill.robot = read.scalar<std::string>(robot, "name", "robot.");
  skill.arm_joints = read.strings(robot, "arm_joints", "robot.");
  if (skill.arm_joints.empty())
    read.fail("robot.arm_joints", "empty");
  skill.tcp_link = read.scalar<std::string>(robot, "tcp_link", "robot.");
  skill.gripper_joint = read.scalar<std::string>(robot, "gripper_joint", "robot.");
  skill.joints_home = read.numbers(robot, "home", "robot.", skill.arm_joints.size());
  const YAML::Node object = read.child(root, "object", "");
  skill.object = read.scalar<std::string>(object, "name", "object.");
  skill.object_start = read.pose(object, "start", "object.");
  skill.object_end = read.pose(object, "end", "object.");
  skill.object_in_hand = read.pose(object, "in_hand", "object.");
  const YAML::Node place = read.child(root, "place_on", "");
  skill.place_on = read.scalar<std::string>(place, "name", "place_on.");
  if (!skill.place_on.empty())
    skill.place_start = read.pose(place, "start", "place_on.");
  const YAML::Node instructions = read.child(root, "instructions", "");
  if (!instructions.IsSequence() || instructions.size() == 0)
    read.fail("instructions", "expected a non-empty list");
  for (std::size_t i = 0; i < instructions.size(); ++i)
    skill.instructions.push_back(readInstruction(instructions[i], read, "instructions[" + std::to_string(i) + "].",
                                                 skill.arm_joints.size()));
  const YAML::Node sources = read.child(root, "sources", "");
  if (!sources.IsSequence())
    read.fail("sources", "expected a list");
  for (std::size_t i = 0; i < sources.size(); ++i)
    skill.sources.push_back(readSource(sources[i], read, "sources[" + std::to_string(i) + "]."));
  skill.created = read.scalar<std::string>(root, "created", "");
  skill.tool = read.scalar<std::string>(root, "tool", "");
  return skill;
}
}  // namespace

std::string toYaml(const Skill& skill)
{
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << Skill::kFormat;
  out << YAML::Key << "robot" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << skill.robot;
  out << YAML::Key << "arm_joints" << YAML::Value << YAML::Flow << skill.arm_joints;
  out << YAML::Key << "tcp_link" << YAML::Value << skill.tcp_link;
  out << YAML::Key << "gripper_joint" << YAML::Value << skill.gripper_joint;
  out << YAML::Key << "home" << YAML::Value;
  emitNumbers(out, skill.joints_home);
  out << YAML::EndMap;
  out << YAML::Key << "object" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << skill.object;
  pose(out, "start", skill.object_start);
  pose(out, "end", skill.object_end);
  pose(out, "in_hand", skill.object_in_hand);
  out << YAML::EndMap;
  out << YAML::Key << "place_on" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << skill.place_on;
  if (!skill.place_on.empty())
    pose(out, "start", skill.place_start);
  out << YAML::EndMap;
  out << YAML::Key << "instructions" << YAML::Value << YAML::BeginSeq;
  for (const SkillInstruction& value : skill.instructions)
    instruction(out, value);
  out << YAML::EndSeq;
  out << YAML::Key << "sources" << YAML::Value << YAML::BeginSeq;
  for (const SkillSource& value : skill.sources)
    source(out, value);
  out << YAML::EndSeq;
  out << YAML::Key << "created" << YAML::Value << skill.created;
  out << YAML::Key << "tool" << YAML::Value << skill.tool;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

Skill fromYaml(const std::string& text, const std::string& source)
{
  const Reader read(source);
  YAML::Node root;
  try
  {
    root = vrrw_dmp::loadYamlMapping(text, source, "skill");
  }
  catch (const vrrw_dmp::DmpError& e)
  {
    throw SkillError(e.what());
  }
  try
  {
    return parse(root, read);
  }
  catch (const vrrw_dmp::DmpError& e)
  {
    throw SkillError(e.what());
  }
  catch (const YAML::Exception& e)
  {
    throw SkillError(source + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

void saveSkill(const Skill& skill, const std::string& path)
{
  struct stat info;
  if (::stat(path.c_str(), &info) == 0)
    throw SkillError(path + ": exists; not overwritten (remove it or choose another name)");
  try
  {
    vrrw_trajectory::writeWholeFile(path, toYaml(skill));
  }
  catch (const vrrw_trajectory::TrajectoryError& e)
  {
    throw SkillError(e.what());
  }
}

Skill loadSkill(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    throw SkillError(path + ": cannot open for reading (no such file?)");
  const std::streamoff size = in.tellg();
  if (size > kMaxFileBytes)
    throw SkillError(path + ": " + std::to_string(size) + " bytes, more than a skill file's limit of " +
                     std::to_string(kMaxFileBytes));
  in.seekg(0);
  std::stringstream text;
  text << in.rdbuf();
  return fromYaml(text.str(), path);
}
}  // namespace vrrw_skills
