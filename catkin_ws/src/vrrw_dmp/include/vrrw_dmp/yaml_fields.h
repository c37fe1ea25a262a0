#pragma once
// The one reader of YAML fields for model files (dmp_yaml) and skill files (vrrw_skills, which adds its poses
// and keyframes): every refusal one line naming the file and the field.
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <vrrw_dmp/dmp_error.h>

namespace vrrw_dmp
{
/// \brief Reads the fields of a YAML document; each refusal throws DmpError `SOURCE: path.to.field: reason`.
class YamlFields
{
public:
  /// \a what names the document's top level in errors ("model", "skill").
  YamlFields(std::string source, std::string what) : source_(std::move(source)), what_(std::move(what)) {}

  /// \brief node[key]; refuses a \a node that is no mapping and a missing key.
  YAML::Node child(const YAML::Node& node, const std::string& key, const std::string& path) const;

  /// \brief A scalar as T: a string, or a number (a floating-point one finite).
  template <typename T>
  T scalar(const YAML::Node& node, const std::string& key, const std::string& path) const
  {
    const YAML::Node value = child(node, key, path);
    try
    {
      if (!value.IsScalar())
        throw YAML::Exception(YAML::Mark::null_mark(), "");
      const T read = value.as<T>();
      if constexpr (std::is_floating_point<T>::value)
        if (!std::isfinite(read))
          fail(path + key, "is not a finite number");
      return read;
    }
    catch (const YAML::Exception&)
    {
      fail(path + key, std::is_same<T, std::string>::value ? "is not a string" : "is not a number");
    }
  }

  /// \brief A list of finite numbers; of \a size numbers when \a size is not 0.
  std::vector<double> numbers(const YAML::Node& node, const std::string& key, const std::string& path,
                              std::size_t size = 0) const;
  /// \brief A list of names.
  std::vector<std::string> strings(const YAML::Node& node, const std::string& key, const std::string& path) const;

  const std::string& source() const { return source_; }

  [[noreturn]] void fail(const std::string& field, const std::string& reason) const
  {
    throw DmpError(source_ + ": " + field + ": " + reason);
  }

private:
  std::string source_;
  std::string what_;
};
}  // namespace vrrw_dmp
