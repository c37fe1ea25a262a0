#include "catalog.h"

#include "yaml_field.h"

namespace vrrw_scene
{
namespace
{
std::map<std::string, std::string> readArgs(const YamlField& entry)
{
  std::map<std::string, std::string> args;
  if (entry.has("args"))
    for (const auto& key : entry["args"].keys())
      args[key] = entry["args"][key].asString();
  return args;
}

std::vector<std::string> stringsOr(const YamlField& entry, const std::string& key)
{
  return entry.has(key) ? entry[key].asStrings() : std::vector<std::string>{};
}
}  // namespace

Catalog Catalog::load(const std::string& urdf_dir)
{
  const auto file = YamlField::loadFile(urdf_dir + "/models.yaml");
  file.allowKeys({ "robots", "grippers", "objects" });
  Catalog catalog;
  for (const auto& name : file["robots"].keys())
  {
    const auto entry = file["robots"][name];
    entry.allowKeys({ "xacro", "macro", "args", "config", "base_link", "arm_base_link", "tool_link", "builtin_gripper",
                      "gripper_joints", "arm_joints", "initial" });
    RobotModel model;
    model.xacro = entry["xacro"].asString();
    model.macro = entry["macro"].asString();
    model.config = entry.stringOr("config", "");
    model.args = readArgs(entry);
    model.base_link = entry["base_link"].asString();
    model.arm_base_link = entry.stringOr("arm_base_link", model.base_link);
    model.tool_link = entry["tool_link"].asString();
    model.builtin_gripper = entry.stringOr("builtin_gripper", "");
    model.arm_joints = entry["arm_joints"].asStrings();
    model.gripper_joints = stringsOr(entry, "gripper_joints");
    if (entry.has("initial"))
      for (const auto& joint : entry["initial"].keys())
        model.initial[joint] = entry["initial"][joint].asDouble();
    catalog.robots[name] = model;
  }
  for (const auto& name : file["grippers"].keys())
  {
    const auto entry = file["grippers"][name];
    entry.allowKeys({ "xacro", "macro", "args", "config", "joints" });
    catalog.grippers[name] = GripperModel{ entry["xacro"].asString(), entry["macro"].asString(),
                                           entry.stringOr("config", ""), readArgs(entry), entry["joints"].asStrings() };
  }
  for (const auto& name : file["objects"].keys())
  {
    const auto entry = file["objects"][name];
    entry.allowKeys({ "xacro", "macro", "fixed" });
    catalog.objects[name] = ObjectKind{ entry["xacro"].asString(), entry["macro"].asString(),
                                        entry.has("fixed") && entry["fixed"].asBool() };
  }
  return catalog;
}
}  // namespace vrrw_scene
