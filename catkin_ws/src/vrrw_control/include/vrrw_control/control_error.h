#pragma once
#include <stdexcept>
#include <string>

namespace vrrw_control
{
/// \brief What vrrw_control's library and ROS layer throw for a robot they cannot drive as configured (a URDF
/// without a joint, a controller's joint the hardware lacks, an empty trajectory): one line,
/// `<what>: <field>: <reason>`. A goal's problems are not thrown: the validator answers them (REJECTED).
class ControlError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};
}  // namespace vrrw_control
