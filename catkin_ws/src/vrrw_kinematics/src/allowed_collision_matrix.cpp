#include "vrrw_kinematics/allowed_collision_matrix.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace vrrw_kinematics
{
std::pair<std::string, std::string> AllowedCollisionMatrix::ordered(const std::string& a, const std::string& b)
{
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

void AllowedCollisionMatrix::allow(const std::string& a, const std::string& b, const std::string& reason)
{
  entries_[ordered(a, b)] = reason;
}

void AllowedCollisionMatrix::forbid(const std::string& a, const std::string& b)
{
  entries_.erase(ordered(a, b));
}

bool AllowedCollisionMatrix::allowed(const std::string& a, const std::string& b) const
{
  return entries_.count(ordered(a, b)) > 0;
}

std::string AllowedCollisionMatrix::reason(const std::string& a, const std::string& b) const
{
  const auto it = entries_.find(ordered(a, b));
  return it == entries_.end() ? "" : it->second;
}

std::size_t AllowedCollisionMatrix::count(const std::string& reason) const
{
  std::size_t n = 0;
  for (const auto& entry : entries_)
    n += entry.second == reason ? 1 : 0;
  return n;
}

void AllowedCollisionMatrix::save(const std::string& path, const std::string& key) const
{
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary);
    if (!out)
      return;
    out << "# " << key << "\n";
    for (const auto& entry : entries_)
      out << entry.first.first << " " << entry.first.second << " " << entry.second << "\n";
  }
  std::rename(temporary.c_str(), path.c_str());
}

bool AllowedCollisionMatrix::load(const std::string& path, const std::string& key)
{
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line) || line != "# " + key)
    return false;
  entries_.clear();
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string a, b, reason;
    if (fields >> a >> b >> reason)
      allow(a, b, reason);
  }
  return true;
}
}  // namespace vrrw_kinematics
