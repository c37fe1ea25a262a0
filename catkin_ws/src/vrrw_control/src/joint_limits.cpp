#include <urdf_parser/urdf_parser.h>
#include <vrrw_control/control_error.h>
#include <vrrw_control/joint_limits.h>

namespace vrrw_control
{
std::vector<JointLimits> loadJointLimits(const std::string& urdf_xml, const std::vector<std::string>& joints,
                                         const std::map<std::string, double>& acceleration_limits)
{
  const auto model = urdf::parseURDF(urdf_xml);
  if (!model)
    throw ControlError("robot_description: not a valid URDF");
  std::vector<JointLimits> result;
  for (const auto& name : joints)
  {
    const auto joint = model->getJoint(name);
    if (!joint)
      throw ControlError("robot_description: joint " + name + ": not in the URDF");
    JointLimits l;
    l.name = name;
    if (joint->limits)
    {
      if (joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::PRISMATIC)
      {
        l.has_position_limits = true;
        l.min_position = joint->limits->lower;
        l.max_position = joint->limits->upper;
      }
      if (joint->limits->velocity > 0.0)
        l.max_velocity = joint->limits->velocity;
    }
    if (acceleration_limits.count(name))
      l.max_acceleration = acceleration_limits.at(name);
    result.push_back(l);
  }
  return result;
}
}  // namespace vrrw_control
