#include <vrrw_dmp/yaml_fields.h>

namespace vrrw_dmp
{
YAML::Node YamlFields::child(const YAML::Node& node, const std::string& key, const std::string& path) const
{
  if (!node.IsMap())
    fail(path.empty() ? what_ : path.substr(0, path.size() - 1), "expected a mapping");
  const YAML::Node value = node[key];
  if (!value)
    fail(path + key, "missing");
  return value;
}

std::vector<double> YamlFields::numbers(const YAML::Node& node, const std::string& key, const std::string& path,
                                        std::size_t size) const
{
  const YAML::Node value = child(node, key, path);
  std::vector<double> read;
  try
  {
    if (!value.IsSequence())
      throw YAML::Exception(YAML::Mark::null_mark(), "");
    read = value.as<std::vector<double>>();
  }
  catch (const YAML::Exception&)
  {
    fail(path + key, "is not a list of numbers");
  }
  for (double v : read)
    if (!std::isfinite(v))
      fail(path + key, "holds a number that is not finite");
  if (size > 0 && read.size() != size)
    fail(path + key, std::to_string(read.size()) + " numbers, expected " + std::to_string(size));
  return read;
}

std::vector<std::string> YamlFields::strings(const YAML::Node& node, const std::string& key,
                                             const std::string& path) const
{
  const YAML::Node value = child(node, key, path);
  try
  {
    if (!value.IsSequence())
      throw YAML::Exception(YAML::Mark::null_mark(), "");
    return value.as<std::vector<std::string>>();
  }
  catch (const YAML::Exception&)
  {
    fail(path + key, "is not a list of names");
  }
}
}  // namespace vrrw_dmp
