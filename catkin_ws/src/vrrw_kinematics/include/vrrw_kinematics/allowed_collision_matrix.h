#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vrrw_kinematics
{
/// \brief Body pairs that are never checked, each with the reason (adjacent, always, never, attached, user).
class AllowedCollisionMatrix
{
public:
  void allow(const std::string& a, const std::string& b, const std::string& reason);
  void forbid(const std::string& a, const std::string& b);
  bool allowed(const std::string& a, const std::string& b) const;
  /// \brief Reason a pair is allowed, "" when it is checked.
  std::string reason(const std::string& a, const std::string& b) const;
  std::size_t size() const { return entries_.size(); }
  std::size_t count(const std::string& reason) const;
  const std::map<std::pair<std::string, std::string>, std::string>& entries() const { return entries_; }

  /// \brief Writes "a b reason" lines after a "# key" header line.
  void save(const std::string& path, const std::string& key) const;
  /// \brief Reads a file written by save(); false when missing, unreadable or its key differs.
  bool load(const std::string& path, const std::string& key);

private:
  static std::pair<std::string, std::string> ordered(const std::string& a, const std::string& b);
  std::map<std::pair<std::string, std::string>, std::string> entries_;
};
}  // namespace vrrw_kinematics
