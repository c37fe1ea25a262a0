#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_evaluation
{
/// \brief What vrrw_evaluation's library throws for a demonstration, a path or a report it cannot use: one line,
/// `<what>: <field>: <reason>` (`demonstration.bag: annotations: pick has no end`).
class EvaluationError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};
}  // namespace vrrw_evaluation
