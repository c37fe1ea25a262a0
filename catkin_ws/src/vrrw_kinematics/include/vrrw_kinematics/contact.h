#pragma once
#include <string>

namespace vrrw_kinematics
{
/// \brief Result of a collision check: the first colliding pair found.
struct Contact
{
  bool collision = false;
  std::string body_a;  ///< a link or object name
  std::string body_b;
};
}  // namespace vrrw_kinematics
