#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_demos
{
/// \brief Bad demonstration input; what() is one line naming the file, topic or field and the reason.
class DemoError : public std::runtime_error
{
public:
  explicit DemoError(const std::string& what) : std::runtime_error(what) {}
};
}  // namespace vrrw_demos
