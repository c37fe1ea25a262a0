#pragma once
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_dmp
{
/// \brief A command-line mistake; what() is one line naming the option.
class OptionError : public std::runtime_error
{
public:
  explicit OptionError(const std::string& what) : std::runtime_error(what) {}
};

/// \brief `--key value` and `--key=value` options. The word after `--key` is always its value, so
/// `--goal -0.5,1.2` works as well as `--goal=-0.5,1.2`. Keys may repeat (all() returns every value).
class Options
{
public:
  /// \brief Parses argv[first..argc); every key must be in \a known. Throws OptionError.
  Options(int argc, const char* const* argv, int first, const std::set<std::string>& known);

  bool has(const std::string& key) const { return values_.count(key) > 0; }
  /// \brief The (last) value of a required option.
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  std::vector<std::string> all(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  std::size_t count(const std::string& key, std::size_t fallback) const;
  /// \brief Comma-separated numbers, e.g. "0.1,-1.57,0"; empty when the option is absent.
  std::vector<double> numbers(const std::string& key) const;

private:
  std::map<std::string, std::vector<std::string>> values_;
};

/// \brief Parses a whole cell as a finite double; throws OptionError naming \a what.
double parseNumber(const std::string& text, const std::string& what);
}  // namespace vrrw_dmp
