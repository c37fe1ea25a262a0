#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_trajectory
{
/// \brief Bad trajectory input; what() is one line naming the thing, e.g. "demo.csv:7: time 0.2 is not after 0.3".
class TrajectoryError : public std::runtime_error
{
public:
  explicit TrajectoryError(const std::string& what) : std::runtime_error(what) {}
};
}  // namespace vrrw_trajectory
