#pragma once
// The vrrw_demos tests read a written file whole, to compare it or search it.
#include <fstream>
#include <sstream>
#include <string>

/// The whole text of the file at `path` (empty when it cannot be read).
inline std::string slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
