#include <vrrw_physics/drive_mode.h>

#include <stdexcept>

namespace vrrw_physics
{
DriveMode parseDriveMode(const std::string& text)
{
  if (text == "rigid")
    return DriveMode::Rigid;
  if (text == "compliant")
    return DriveMode::Compliant;
  if (text == "custom")
    return DriveMode::Custom;
  throw std::invalid_argument("mode '" + text + "': expected rigid, compliant or custom");
}

const char* toString(DriveMode mode)
{
  switch (mode)
  {
    case DriveMode::Rigid:
      return "rigid";
    case DriveMode::Compliant:
      return "compliant";
    case DriveMode::Custom:
      return "custom";
  }
  return "?";
}
}  // namespace vrrw_physics
