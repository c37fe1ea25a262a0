#pragma once
// Conversions between vrrw_physics' library types and the messages physics_node speaks.
#include <vrrw_physics/Contacts.h>
#include <vrrw_physics/SetSpring.h>
#include <vrrw_physics/physics_world.h>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Vector3.h>
#include <sensor_msgs/JointState.h>

namespace vrrw_physics
{
/// \brief A pose message as an isometry (quaternion normalized); throws InputError for a zero or
/// non-finite quaternion.
Eigen::Isometry3d toEigen(const geometry_msgs::Pose& pose);
Eigen::Vector3d toEigen(const geometry_msgs::Vector3& vector);
/// \brief tf of `child` in `parent`.
geometry_msgs::TransformStamped toTransform(const Eigen::Isometry3d& pose, const std::string& parent,
                                            const std::string& child, ros::Time stamp);
/// \brief The spring a set_spring request attaches (max_force 0: OperatorSpring's default).
OperatorSpring toSpring(const SetSpring::Request& request);
sensor_msgs::JointState toMsg(const JointStates& states, ros::Time stamp);
/// \brief Adds one robot's joints to a message of several.
void append(const sensor_msgs::JointState& robot, sensor_msgs::JointState& all);
Contacts toMsg(const std::vector<ContactPair>& contacts, ros::Time stamp);
}  // namespace vrrw_physics
