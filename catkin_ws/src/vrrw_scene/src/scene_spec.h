#pragma once
#include <Eigen/Geometry>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "catalog.h"

namespace vrrw_scene
{
/// \brief A robot as the scene YAML names it, checked against the catalogue.
struct RobotSpec
{
  std::string name, model, gripper;
  std::string description;  ///< a custom URDF or xacro file, in place of a catalogue model
  std::string tip_link;     ///< custom robots: end of the arm chain
  std::string config;       ///< acceleration limits and gains, in place of the catalogue's
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  std::map<std::string, double> initial;  ///< unprefixed joint names
  std::string field;                      ///< "file:line: robots[i]" for later errors
};

/// \brief An object as the scene YAML names it, random placement already drawn.
struct ObjectSpec
{
  std::string name, kind;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::optional<double> mass, friction, restitution;
  std::optional<bool> fixed;
  Eigen::Vector3d size = Eigen::Vector3d(0.1, 0.1, 0.1);
  double radius = 0.05, length = 0.1;
  std::string mesh;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  std::optional<std::array<float, 4>> color;
  std::string field;
};

struct SceneSpec
{
  std::string name, file;
  unsigned seed = 0;
  std::vector<RobotSpec> robots;
  std::vector<ObjectSpec> objects;
};

/// \brief Reads and checks a scene YAML; throws SceneError naming file, line, field and reason.
SceneSpec parseSceneFile(const std::string& file, const Catalog& catalog);
}  // namespace vrrw_scene
