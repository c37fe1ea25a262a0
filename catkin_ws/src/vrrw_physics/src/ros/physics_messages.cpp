#include "physics_messages.h"

#include <cmath>

namespace vrrw_physics
{
Eigen::Isometry3d toEigen(const geometry_msgs::Pose& p)
{
  const Eigen::Quaterniond q(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
  if (!(q.norm() > 1e-9) || !std::isfinite(q.norm()))
    throw InputError("pose: orientation quaternion is zero or not finite");
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  t.linear() = q.normalized().toRotationMatrix();
  return t;
}

Eigen::Vector3d toEigen(const geometry_msgs::Vector3& v)
{
  return Eigen::Vector3d(v.x, v.y, v.z);
}

geometry_msgs::TransformStamped toTransform(const Eigen::Isometry3d& pose, const std::string& parent,
                                            const std::string& child, ros::Time stamp)
{
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  const Eigen::Quaterniond q(pose.rotation());
  t.transform.translation.x = pose.translation().x();
  t.transform.translation.y = pose.translation().y();
  t.transform.translation.z = pose.translation().z();
  t.transform.rotation.w = q.w();
  t.transform.rotation.x = q.x();
  t.transform.rotation.y = q.y();
  t.transform.rotation.z = q.z();
  return t;
}

OperatorSpring toSpring(const SetSpring::Request& req)
{
  OperatorSpring spring;
  spring.body = req.body;
  spring.point = Eigen::Vector3d(req.point.x, req.point.y, req.point.z);
  spring.target = toEigen(req.target);
  spring.stiffness = req.stiffness;
  spring.damping = req.damping;
  spring.angular_stiffness = req.angular_stiffness;
  spring.angular_damping = req.angular_damping;
  if (req.max_force != 0.0)
    spring.max_force = req.max_force;
  return spring;
}

sensor_msgs::JointState toMsg(const JointStates& s, ros::Time stamp)
{
  sensor_msgs::JointState msg;
  msg.header.stamp = stamp;
  msg.name = s.name;
  msg.position = s.position;
  msg.velocity = s.velocity;
  msg.effort = s.effort;
  return msg;
}

void append(const sensor_msgs::JointState& robot, sensor_msgs::JointState& all)
{
  all.name.insert(all.name.end(), robot.name.begin(), robot.name.end());
  all.position.insert(all.position.end(), robot.position.begin(), robot.position.end());
  all.velocity.insert(all.velocity.end(), robot.velocity.begin(), robot.velocity.end());
  all.effort.insert(all.effort.end(), robot.effort.begin(), robot.effort.end());
}

Contacts toMsg(const std::vector<ContactPair>& contacts, ros::Time stamp)
{
  Contacts msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = "world";
  for (const ContactPair& c : contacts)
  {
    vrrw_physics::Contact& out = msg.contacts.emplace_back();
    out.body_a = c.body_a;
    out.body_b = c.body_b;
    out.normal_force = c.normal_force;
    out.position.x = c.position.x();
    out.position.y = c.position.y();
    out.position.z = c.position.z();
  }
  return msg;
}
}  // namespace vrrw_physics
