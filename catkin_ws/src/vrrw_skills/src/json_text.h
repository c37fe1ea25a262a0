#pragma once
// Text into JSON: the skill summary and the evaluation's metrics write strings the same way.
#include <string>

namespace vrrw_skills
{
/// `text` as a JSON string: quotes and backslashes escaped, control characters as spaces.
inline std::string jsonString(const std::string& text)
{
  std::string out = "\"";
  for (char c : text)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  }
  return out + "\"";
}
}  // namespace vrrw_skills
