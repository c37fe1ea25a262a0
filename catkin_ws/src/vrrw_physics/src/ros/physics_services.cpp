// PhysicsNode's services and its one error line per rejected input.
#include "physics_node.h"

#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <vrrw_physics/SetGains.h>
#include <vrrw_physics/SetMode.h>
#include <vrrw_physics/SetObjectPose.h>
#include <vrrw_physics/SetSpring.h>

#include "physics_messages.h"

namespace vrrw_physics
{
void PhysicsNode::advertiseServices(ros::NodeHandle& pnh)
{
  // Gazebo's pause and unpause: answered whatever the state; a second pause changes nothing
  for (const bool pause : { true, false })
    services_.push_back(pnh.advertiseService<std_srvs::Empty::Request, std_srvs::Empty::Response>(
        pause ? "pause" : "unpause", [this, pause](std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
          if (paused_ != pause)
            ROS_INFO_STREAM("physics_node: " << (pause ? "paused" : "running") << " at " << world_.time() << " s");
          paused_ = pause;
          return true;
        }));
  service<std_srvs::Trigger>(pnh, "reset", [this](auto&) {
    world_.reset();
    states_at_ = clock_at_ = ~0ull;
    due_.clear();
    controllers_.interrupt("the simulation was reset");
    stopped();
  });
  service<SetMode>(pnh, "set_mode", [this](auto& req) { world_.setMode(req.robot, parseDriveMode(req.mode)); });
  service<SetGains>(pnh, "set_gains", [this](auto& req) {
    world_.setGains(req.robot, req.joints, req.stiffness, req.damping, req.max_force);
  });
  service<SetSpring>(pnh, "set_spring", [this](auto& req) {
    if (req.release)
      world_.operatorInput().releaseSpring(req.id);
    else
      world_.operatorInput().attachSpring(req.id, toSpring(req));
  });
  // (not published again while paused: tf keeps the first transform of a stamp and warns about every later one in
  // every listener; observers see the object moved at the next step)
  service<SetObjectPose>(pnh, "set_object_pose", [this](auto& req) { world_.setObjectPose(req.object, toEigen(req.pose)); });
}

void PhysicsNode::report(const std::string& source, const std::string& message, bool always)
{
  std_msgs::String msg;
  msg.data = always ? message : throttle_.admit(source, message, ros::WallTime::now().toSec());
  if (!msg.data.empty())
    errors_.publish(msg);
  ROS_ERROR_STREAM_COND(!msg.data.empty(), msg.data);
}

std::string PhysicsNode::guarded(const std::string& source, const std::function<void()>& call)
{
  try
  {
    call();
    return "";
  }
  catch (const std::invalid_argument& e)
  {
    const std::string message = source + ": " + e.what();
    report(source, message);
    return message;
  }
}

template <class Srv, class Call>
void PhysicsNode::service(ros::NodeHandle& pnh, const std::string& name, Call call)
{
  services_.push_back(pnh.advertiseService<typename Srv::Request, typename Srv::Response>(
      name, [this, name, call](typename Srv::Request& req, typename Srv::Response& res) {
        const std::string error = guarded(name, [&] { call(req); });
        res.success = error.empty();
        res.message = error.empty() ? "ok" : error;
        return true;
      }));
}
}  // namespace vrrw_physics
