#pragma once
#include <map>
#include <string>
#include <vector>

namespace vrrw_scene
{
/// \brief How a robot model is built and what its arm is (urdf/models.yaml).
struct RobotModel
{
  std::string xacro, macro, config;
  std::map<std::string, std::string> args;
  std::string base_link, arm_base_link, tool_link, builtin_gripper;
  std::vector<std::string> arm_joints, gripper_joints;
  std::map<std::string, double> initial;
};

struct GripperModel
{
  std::string xacro, macro, config;
  std::map<std::string, std::string> args;
  std::vector<std::string> joints;
};

struct ObjectKind
{
  std::string xacro, macro;
  bool fixed = false;
};

/// \brief The robots, grippers and object kinds a scene may name (urdf/models.yaml).
struct Catalog
{
  std::map<std::string, RobotModel> robots;
  std::map<std::string, GripperModel> grippers;
  std::map<std::string, ObjectKind> objects;

  static Catalog load(const std::string& urdf_dir);
};

/// \brief "a, b, c" of a map's keys, for error messages.
template <class Map>
std::string keyList(const Map& map)
{
  std::string out;
  for (const auto& item : map)
    out += (out.empty() ? "" : ", ") + item.first;
  return out;
}
}  // namespace vrrw_scene
