#include "physics_operator.h"

#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_physics/Hand.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetSpring.h>
#include <vrrw_physics/SpringTarget.h>

namespace vrrw_interaction
{
namespace
{
/// One call of the physics node (vrrw_common's persistent links: ros_comm#1976): false when the call failed or
/// the answer says so. A short wait for a missing service (the physics node is either up or not).
template <class Service>
bool call(const std::string& name, Service& srv)
{
  static auto* services = new vrrw_common::PersistentServices({ 0.2, 5.0 });  // never destroyed: not after roscpp
  return services->tryCall(name, srv) && srv.response.success;
}
}  // namespace

PhysicsOperator::PhysicsOperator(const SpringGains& gains) : gains_(gains)
{
  ros::NodeHandle nh;
  spring_target_ = nh.advertise<vrrw_physics::SpringTarget>("/physics/spring_target", 10);
  hand_ = nh.advertise<vrrw_physics::Hand>("/physics/hand", 10);
}

Outcome PhysicsOperator::setMode(const std::string& robot, bool compliant)
{
  vrrw_physics::SetMode srv;
  srv.request.robot = robot;
  srv.request.mode = compliant ? "compliant" : "rigid";
  if (call("/physics/set_mode", srv))
    return { true, srv.request.mode };
  return { false, "/physics/set_mode " + srv.request.mode + " failed: " +
                      (srv.response.message.empty() ? "is the physics node running?" : srv.response.message) };
}

bool PhysicsOperator::attach(const std::string& id, const std::string& body, const Eigen::Vector3d& point,
                             const Eigen::Isometry3d& target, bool angular)
{
  vrrw_physics::SetSpring srv;
  srv.request.id = id;
  srv.request.body = body;
  srv.request.point = tf2::toMsg(point);
  srv.request.target = tf2::toMsg(target);
  srv.request.stiffness = gains_.stiffness, srv.request.damping = gains_.damping;
  srv.request.max_force = gains_.max_force;
  if (angular)
    srv.request.angular_stiffness = gains_.angular_stiffness, srv.request.angular_damping = gains_.angular_damping;
  if (call("/physics/set_spring", srv))
    return true;
  ROS_WARN_STREAM("/physics/set_spring " << id << " on " << body << ": "
                                         << (srv.response.message.empty() ? "no physics node" : srv.response.message));
  return false;
}

void PhysicsOperator::release(const std::string& id, const std::string& body)
{
  vrrw_physics::SetSpring srv;
  srv.request.id = id;
  srv.request.body = body;
  srv.request.target.orientation.w = 1.0;
  srv.request.release = true;
  if (!call("/physics/set_spring", srv))
    ROS_WARN_STREAM("/physics/set_spring release " << id << ": " << srv.response.message);
}

ros::Time PhysicsOperator::applied(const ros::Time& stamp)
{
  // A script that steps the simulation sends its hand ahead of simulated time (at most a step slice): its stamps
  // make the pull deterministic. A person's tracker is at most a few ms off; a second is neither.
  return stamp <= ros::Time::now() + ros::Duration(1.0) ? stamp : ros::Time();
}

void PhysicsOperator::moveTarget(const std::string& id, const Eigen::Isometry3d& target, const ros::Time& stamp)
{
  vrrw_physics::SpringTarget msg;
  msg.header.stamp = applied(stamp);
  msg.id = id;
  msg.target = tf2::toMsg(target);
  spring_target_.publish(msg);
}

void PhysicsOperator::hand(const std::string& id, const Eigen::Isometry3d& pose, double radius, const ros::Time& stamp)
{
  vrrw_physics::Hand msg;
  msg.header.stamp = applied(stamp);
  msg.id = id;
  msg.pose = tf2::toMsg(pose);
  msg.radius = radius;
  hand_.publish(msg);
}
}  // namespace vrrw_interaction
