#pragma once
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_demos
{
/// \brief `vrrw demos COMMAND POSITIONAL --key value ...` (also `--key=value`; `--yes` takes no value).
class ToolOptions
{
public:
  /// \brief Parses argv[first..argc); keys must be in \a known, \a flags take no value. Throws std::runtime_error.
  ToolOptions(int argc, char** argv, int first, const std::set<std::string>& known,
              const std::set<std::string>& flags = {})
  {
    for (int i = first; i < argc; ++i)
    {
      std::string word = argv[i];
      if (word.rfind("--", 0) != 0)
      {
        positional.push_back(word);
        continue;
      }
      std::string key = word.substr(2), value;
      const auto equals = key.find('=');
      if (equals != std::string::npos)
      {
        value = key.substr(equals + 1);
        key = key.substr(0, equals);
      }
      else if (!flags.count(key))
      {
        if (i + 1 >= argc)
          throw std::runtime_error("option --" + key + " needs a value");
        value = argv[++i];
      }
      if (!known.count(key) && !flags.count(key))
        throw std::runtime_error("unknown option --" + key);
      values[key] = value;
    }
  }

  bool has(const std::string& key) const { return values.count(key) > 0; }
  std::string text(const std::string& key, const std::string& fallback = "") const
  {
    const auto found = values.find(key);
    return found == values.end() ? fallback : found->second;
  }
  double number(const std::string& key, double fallback) const
  {
    if (!has(key))
      return fallback;
    std::size_t used = 0;
    double value = 0;
    try
    {
      value = std::stod(text(key), &used);
    }
    catch (const std::exception&)
    {
    }
    if (used == 0 || used != text(key).size())
      throw std::runtime_error("--" + key + ": '" + text(key) + "' is not a number");
    return value;
  }

  std::vector<std::string> positional;
  std::map<std::string, std::string> values;
};
}  // namespace vrrw_demos
