#include "options.h"

#include <charconv>
#include <cmath>

namespace vrrw_dmp
{
double parseNumber(const std::string& text, const std::string& what)
{
  double value = 0.0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+')
    ++begin;
  const auto result = std::from_chars(begin, end, value);
  if (text.empty() || result.ec != std::errc() || result.ptr != end || !std::isfinite(value))
    throw OptionError(what + ": '" + text + "' is not a finite number");
  return value;
}

Options::Options(int argc, const char* const* argv, int first, const std::set<std::string>& known)
{
  for (int i = first; i < argc; ++i)
  {
    const std::string word = argv[i];
    if (word.rfind("--", 0) != 0 || word.size() == 2)
      throw OptionError("unexpected argument '" + word + "' (options are --key value or --key=value)");
    const auto equals = word.find('=');
    const std::string key = word.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    if (known.count(key) == 0)
      throw OptionError("unknown option --" + key);
    if (equals != std::string::npos)
      values_[key].push_back(word.substr(equals + 1));
    else if (i + 1 < argc)
      values_[key].push_back(argv[++i]);
    else
      throw OptionError("--" + key + " needs a value");
  }
}

std::string Options::text(const std::string& key) const
{
  const auto found = values_.find(key);
  if (found == values_.end())
    throw OptionError("--" + key + " is required");
  return found->second.back();
}

std::string Options::text(const std::string& key, const std::string& fallback) const
{
  return has(key) ? text(key) : fallback;
}

std::vector<std::string> Options::all(const std::string& key) const
{
  const auto found = values_.find(key);
  return found == values_.end() ? std::vector<std::string>{} : found->second;
}

double Options::number(const std::string& key, double fallback) const
{
  return has(key) ? parseNumber(text(key), "--" + key) : fallback;
}

std::size_t Options::count(const std::string& key, std::size_t fallback) const
{
  if (!has(key))
    return fallback;
  const std::string value = text(key);
  const double number = parseNumber(value, "--" + key);
  if (number < 0.0 || number != std::floor(number) || number > 1e9)
    throw OptionError("--" + key + ": '" + value + "' is not a whole number >= 0");
  return static_cast<std::size_t>(number);
}

std::vector<double> Options::numbers(const std::string& key) const
{
  std::vector<double> result;
  if (!has(key))
    return result;
  const std::string value = text(key);
  std::string::size_type begin = 0;
  for (std::size_t index = 1;; ++index)
  {
    const auto comma = value.find(',', begin);
    const std::string cell = value.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    result.push_back(parseNumber(cell, "--" + key + " value " + std::to_string(index)));
    if (comma == std::string::npos)
      return result;
    begin = comma + 1;
  }
}
}  // namespace vrrw_dmp
