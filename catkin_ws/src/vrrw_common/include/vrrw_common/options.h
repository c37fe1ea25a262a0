#pragma once
// The one option parser of every command-line tool: `TOOL COMMAND POSITIONAL... --key value --key=value --flag`.
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_common
{
/// \brief A command-line mistake; what() is one line naming the option, e.g. `--trials: needs a value`.
class OptionError : public std::invalid_argument
{
public:
  explicit OptionError(const std::string& what) : std::invalid_argument(what) {}
};

/// \brief An interval a number must lie in, written as it is printed: `(0, 86400] s`.
struct Range
{
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;  ///< lo itself is outside
  bool hi_open = false;  ///< hi itself is outside
  std::string unit;      ///< printed after the interval ("s", "rad"); empty for none

  static Range closed(double lo, double hi, const std::string& unit = "") { return { lo, hi, false, false, unit }; }
  /// \brief (lo, hi]: e.g. a duration that must be positive.
  static Range aboveUpTo(double lo, double hi, const std::string& unit = "") { return { lo, hi, true, false, unit }; }
  bool contains(double value) const;
  /// \brief `[lo, hi] unit`, e.g. `(0, 86400] s`.
  std::string text() const;
};

/// \brief The words of a command line after the command: positional words, `--key value`, `--key=value`, and
/// flags without a value. Only known keys are accepted; the word after a valued key is always its value (so
/// `--goal -0.5,1.2` works); a key given twice keeps every value and reads as the last. Typed getters check
/// the value and throw OptionError naming the option.
class Options
{
public:
  /// \brief Parses argv[first..argc). \a valued keys take a value, \a flags take none (`--yes`).
  Options(int argc, const char* const* argv, int first, const std::set<std::string>& valued,
          const std::set<std::string>& flags = {});
  Options(int argc, char** argv, int first, const std::set<std::string>& valued,
          const std::set<std::string>& flags = {})
    : Options(argc, const_cast<const char* const*>(argv), first, valued, flags)
  {
  }

  /// \brief The positional words in order.
  const std::vector<std::string>& positional() const { return positional_; }
  /// \brief Checks there are exactly names.size() positional words, refusing `missing BAG` or `unexpected
  /// argument 'x'`.
  void expectPositional(const std::vector<std::string>& names) const;

  bool has(const std::string& key) const { return values_.count(key) > 0; }
  /// \brief A flag was given.
  bool flag(const std::string& key) const { return has(key); }

  /// \brief The value of a required option (`--csv: required` when absent).
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  /// \brief Every value of a key given more than once, in order.
  std::vector<std::string> all(const std::string& key) const;

  /// \brief A finite number within \a range: `--duration: 1e10 outside (0, 86400] s`.
  double number(const std::string& key, const Range& range = Range()) const;
  double number(const std::string& key, double fallback, const Range& range = Range()) const;

  /// \brief A whole number in [lo, hi]: `--trials: -1 is not a whole number >= 1` (kMaxCount: no upper bound
  /// but what a double holds exactly).
  std::uint64_t count(const std::string& key, std::uint64_t lo, std::uint64_t hi) const;
  std::uint64_t count(const std::string& key, std::uint64_t fallback, std::uint64_t lo, std::uint64_t hi) const;

  /// \brief Comma-separated finite numbers, each within \a range; exactly \a size of them when size > 0
  /// (`--joints: 5 values, expected 6`). Empty when the option is absent.
  std::vector<double> list(const std::string& key, std::size_t size = 0, const Range& range = Range()) const;

  /// \brief One of \a choices: `--mode: 'x' is not one of fake, physics, real`.
  std::string choice(const std::string& key, const std::set<std::string>& choices) const;
  std::string choice(const std::string& key, const std::string& fallback, const std::set<std::string>& choices) const;

  /// \brief Exactly one of \a keys is given: `give one of --csv, --joints, --gripper`.
  std::string oneOf(const std::vector<std::string>& keys) const;

  /// \brief Largest count accepted by default: every whole number up to it is exact in a double.
  static constexpr std::uint64_t kMaxCount = 9007199254740992ULL;  // 2^53

private:
  std::vector<std::string> positional_;
  std::map<std::string, std::vector<std::string>> values_;
};

/// \brief Parses the whole of \a text as a finite number; throws OptionError `<what>: 'x' is not a number`.
double parseNumber(const std::string& text, const std::string& what);
/// \brief \a text as the user wrote it, cut to a few dozen characters (an error never echoes a megabyte).
std::string quoted(const std::string& text);
}  // namespace vrrw_common
