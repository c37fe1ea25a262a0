#include "vrrw_common/options.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace vrrw_common
{
namespace
{
/// An error echoes at most this many characters of what the user typed.
constexpr std::size_t kEchoLength = 40;

std::string shortNumber(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

/// The text of a number as typed when it is short, else cut.
std::string echo(const std::string& text)
{
  return text.size() <= kEchoLength ? text : text.substr(0, kEchoLength) + "...";
}

bool parses(const std::string& text, double& value)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+')
    ++begin;
  const auto result = std::from_chars(begin, end, value);
  return begin != end && result.ec == std::errc() && result.ptr == end;
}
}  // namespace

bool Range::contains(double value) const
{
  const bool above = lo_open ? value > lo : value >= lo;
  const bool below = hi_open ? value < hi : value <= hi;
  return above && below;
}

std::string Range::text() const
{
  return (lo_open ? "(" : "[") + shortNumber(lo) + ", " + shortNumber(hi) + (hi_open ? ")" : "]") +
         (unit.empty() ? "" : " " + unit);
}

std::string quoted(const std::string& text)
{
  return "'" + echo(text) + "'";
}

double parseNumber(const std::string& text, const std::string& what)
{
  double value = 0.0;
  if (!parses(text, value))
    throw OptionError(what + ": " + quoted(text) + " is not a number");
  if (!std::isfinite(value))
    throw OptionError(what + ": " + quoted(text) + " is not a finite number");
  return value;
}

Options::Options(int argc, const char* const* argv, int first, const std::set<std::string>& valued,
                 const std::set<std::string>& flags)
{
  for (int i = first; i < argc; ++i)
  {
    const std::string word = argv[i];
    if (word.rfind("--", 0) != 0)
    {
      positional_.push_back(word);
      continue;
    }
    const auto equals = word.find('=');
    const std::string key = word.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    const std::string option = "--" + key;
    if (flags.count(key))
    {
      if (equals != std::string::npos)
        throw OptionError(option + ": takes no value");
      values_[key].emplace_back();
      continue;
    }
    if (!valued.count(key))
      throw OptionError(key.empty() ? "unexpected argument '" + echo(word) + "'" : "unknown option " + echo(option));
    std::string value;
    if (equals != std::string::npos)
      value = word.substr(equals + 1);
    else if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0)  // `--out --quick`: --out has none
      value = argv[++i];
    if (value.empty())
      throw OptionError(option + ": needs a value");
    values_[key].push_back(value);
  }
}

void Options::expectPositional(const std::vector<std::string>& names) const
{
  if (positional_.size() < names.size())
    throw OptionError("missing " + names[positional_.size()]);
  if (positional_.size() > names.size())
    throw OptionError("unexpected argument " + quoted(positional_[names.size()]));
}

std::string Options::text(const std::string& key) const
{
  const auto found = values_.find(key);
  if (found == values_.end())
    throw OptionError("--" + key + ": required");
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

double Options::number(const std::string& key, const Range& range) const
{
  const std::string value = text(key);
  const double number = parseNumber(value, "--" + key);
  if (!range.contains(number))
    throw OptionError("--" + key + ": " + echo(value) + " outside " + range.text());
  return number;
}

double Options::number(const std::string& key, double fallback, const Range& range) const
{
  return has(key) ? number(key, range) : fallback;
}

std::uint64_t Options::count(const std::string& key, std::uint64_t lo, std::uint64_t hi) const
{
  const std::string value = text(key);
  const std::string option = "--" + key;
  double number = 0.0;
  const bool numeric = parses(value, number) && std::isfinite(number);
  if (!numeric || number != std::floor(number) || number < static_cast<double>(lo))
    throw OptionError(option + ": " + (numeric ? echo(value) : quoted(value)) + " is not a whole number >= " +
                      std::to_string(lo));
  const OptionError outside(option + ": " + echo(value) + " outside [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + "]");
  // Digits only: read exactly (a double holds whole numbers exactly only up to 2^53); else (1e3) the double.
  std::uint64_t exact = 0;
  const auto result = std::from_chars(value.data(), value.data() + value.size(), exact);
  if (result.ec == std::errc::result_out_of_range)
    throw outside;
  if (result.ec != std::errc() || result.ptr != value.data() + value.size())
  {
    if (number >= 18446744073709551616.0)  // 2^64
      throw outside;
    exact = static_cast<std::uint64_t>(number);
  }
  if (exact > hi)
    throw outside;
  return exact;
}

std::uint64_t Options::count(const std::string& key, std::uint64_t fallback, std::uint64_t lo, std::uint64_t hi) const
{
  return has(key) ? count(key, lo, hi) : fallback;
}

std::vector<double> Options::list(const std::string& key, std::size_t size, const Range& range) const
{
  std::vector<double> result;
  if (!has(key))
    return result;
  const std::string option = "--" + key;
  const std::string value = text(key);
  for (std::string::size_type begin = 0;;)
  {
    const auto comma = value.find(',', begin);
    const std::string cell = value.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    const std::string what = option + " value " + std::to_string(result.size() + 1);
    const double number = parseNumber(cell, what);
    if (!range.contains(number))
      throw OptionError(what + ": " + echo(cell) + " outside " + range.text());
    result.push_back(number);
    if (comma == std::string::npos)
      break;
    begin = comma + 1;
  }
  if (size > 0 && result.size() != size)
    throw OptionError(option + ": " + std::to_string(result.size()) + " value" + (result.size() == 1 ? "" : "s") +
                      ", expected " + std::to_string(size));
  return result;
}

std::string Options::choice(const std::string& key, const std::set<std::string>& choices) const
{
  const std::string value = text(key);
  if (choices.count(value))
    return value;
  std::string names;
  for (const auto& name : choices)
    names += (names.empty() ? "" : ", ") + name;
  throw OptionError("--" + key + ": " + quoted(value) + " is not one of " + names);
}

std::string Options::choice(const std::string& key, const std::string& fallback,
                            const std::set<std::string>& choices) const
{
  return has(key) ? choice(key, choices) : fallback;
}

std::string Options::oneOf(const std::vector<std::string>& keys) const
{
  std::string given, names;
  for (const auto& key : keys)
  {
    names += (names.empty() ? "--" : ", --") + key;
    if (!has(key))
      continue;
    if (!given.empty())
      throw OptionError("--" + given + " and --" + key + " exclude each other");
    given = key;
  }
  if (given.empty())
    throw OptionError("give one of " + names);
  return given;
}
}  // namespace vrrw_common
