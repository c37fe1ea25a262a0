#pragma once
#include <cstdio>
#include <string>

namespace vrrw_dmp
{
/// \brief A number as error and warning messages print it (6 significant digits).
inline std::string format(double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}
}  // namespace vrrw_dmp
