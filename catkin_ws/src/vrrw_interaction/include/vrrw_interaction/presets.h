#pragma once
#include <Eigen/Dense>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_interaction
{
/// \brief A bad preset file or scene `presets:` entry; what() is one line: "file: field: reason".
class PresetError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// \brief Named arm configurations of one robot: its model's (urdf/config/presets.yaml) and its scene's.
class Presets
{
public:
  /// \brief The presets of `model` in `models_file`, then those the scene YAML lists for `robot` under
  /// `presets: {<robot>: {<name>: [q...]}}` (added or overriding). Every preset must have `joints` finite
  /// values. A model without presets has none; throws PresetError.
  static Presets load(const std::string& models_file, const std::string& model, const std::string& scene_file,
                      const std::string& robot, std::size_t joints);

  /// \brief Names, sorted.
  std::vector<std::string> names() const;
  /// \brief The preset `name`; throws PresetError naming the known ones.
  const Eigen::VectorXd& at(const std::string& name) const;
  bool has(const std::string& name) const { return presets_.count(name) > 0; }

private:
  std::map<std::string, Eigen::VectorXd> presets_;
};
}  // namespace vrrw_interaction
