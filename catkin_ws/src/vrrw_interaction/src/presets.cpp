#include <vrrw_interaction/presets.h>

#include <yaml-cpp/yaml.h>
#include <cmath>
#include <fstream>

namespace vrrw_interaction
{
namespace
{
YAML::Node loadYaml(const std::string& file)
{
  if (!std::ifstream(file).good())
    throw PresetError(file + ": cannot be read");
  try
  {
    return YAML::LoadFile(file);
  }
  catch (const YAML::Exception& e)
  {
    throw PresetError(file + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

/// \brief Reads {name: [q...]} of `node` (field path `field`) into `out`.
void readPresets(const YAML::Node& node, const std::string& file, const std::string& field, std::size_t joints,
                 std::map<std::string, Eigen::VectorXd>& out)
{
  if (!node.IsMap())
    throw PresetError(file + ": " + field + ": must be a map of preset names to joint lists");
  for (const auto& entry : node)
  {
    const std::string name = entry.first.as<std::string>();
    const std::string where = file + ": " + field + "." + name;
    if (!entry.second.IsSequence() || entry.second.size() != joints)
      throw PresetError(where + ": must list " + std::to_string(joints) + " joint values (the arm's joints)");
    Eigen::VectorXd q(static_cast<Eigen::Index>(joints));
    for (std::size_t i = 0; i < joints; ++i)
    {
      try
      {
        q[static_cast<Eigen::Index>(i)] = entry.second[i].as<double>();
      }
      catch (const YAML::Exception&)
      {
        throw PresetError(where + "[" + std::to_string(i) + "]: not a number");
      }
      if (!std::isfinite(q[static_cast<Eigen::Index>(i)]))
        throw PresetError(where + "[" + std::to_string(i) + "]: not finite");
    }
    out[name] = q;
  }
}
}  // namespace

Presets Presets::load(const std::string& models_file, const std::string& model, const std::string& scene_file,
                      const std::string& robot, std::size_t joints)
{
  Presets presets;
  const YAML::Node models = loadYaml(models_file);
  if (models[model])
    readPresets(models[model], models_file, model, joints, presets.presets_);
  if (scene_file.empty())
    return presets;
  const YAML::Node scene = loadYaml(scene_file);
  if (scene["presets"] && scene["presets"][robot])
    readPresets(scene["presets"][robot], scene_file, "presets." + robot, joints, presets.presets_);
  return presets;
}

std::vector<std::string> Presets::names() const
{
  std::vector<std::string> names;
  for (const auto& preset : presets_)
    names.push_back(preset.first);
  return names;
}

const Eigen::VectorXd& Presets::at(const std::string& name) const
{
  const auto preset = presets_.find(name);
  if (preset == presets_.end())
  {
    std::string known;
    for (const auto& n : names())
      known += (known.empty() ? "" : ", ") + n;
    throw PresetError("name: unknown preset '" + name + "' (known: " + known + ")");
  }
  return preset->second;
}
}  // namespace vrrw_interaction
