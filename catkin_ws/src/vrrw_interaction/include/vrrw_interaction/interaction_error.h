#pragma once
#include <stdexcept>

namespace vrrw_interaction
{
/// \brief What the library throws for input it cannot use; what() is one line "<what>: <field>: <reason>".
class InteractionError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};
}  // namespace vrrw_interaction
