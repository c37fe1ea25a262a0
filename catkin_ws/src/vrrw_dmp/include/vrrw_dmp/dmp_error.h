#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_dmp
{
/// \brief Bad DMP input or parameters; what() is one line naming the thing and the reason.
class DmpError : public std::runtime_error
{
public:
  explicit DmpError(const std::string& what) : std::runtime_error(what) {}
};
}  // namespace vrrw_dmp
