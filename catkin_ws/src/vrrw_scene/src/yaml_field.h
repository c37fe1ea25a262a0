#pragma once
#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "vrrw_scene/scene.h"

namespace vrrw_scene
{
/// \brief A YAML node with the file and field path it came from, so errors can name both.
class YamlField
{
public:
  YamlField(YAML::Node node, std::string file, std::string path);

  static YamlField loadFile(const std::string& file);

  bool has(const std::string& key) const;
  YamlField operator[](const std::string& key) const;  ///< required key
  YamlField operator[](std::size_t index) const;
  std::size_t size() const;
  std::vector<std::string> keys() const;

  void requireMap() const;
  void requireSequence() const;
  void allowKeys(const std::vector<std::string>& allowed) const;

  double asDouble() const;
  std::string asString() const;
  bool asBool() const;
  std::vector<double> asDoubles(std::size_t expected_size) const;  ///< 0: any size
  std::vector<std::string> asStrings() const;

  double doubleOr(const std::string& key, double fallback) const;
  std::string stringOr(const std::string& key, const std::string& fallback) const;

  /// \brief {xyz: [x, y, z], rpy: [r, p, y]}, both optional.
  Eigen::Isometry3d asPose() const;

  [[noreturn]] void fail(const std::string& reason) const;

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }

private:
  YAML::Node node_;
  std::string file_;
  std::string path_;
};

/// \brief Rotation from roll, pitch, yaw as URDF defines them (fixed axes x, y, z).
Eigen::Matrix3d rpyToMatrix(double roll, double pitch, double yaw);
}  // namespace vrrw_scene
