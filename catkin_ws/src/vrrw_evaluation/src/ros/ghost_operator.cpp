#include "ghost_operator.h"
#include "workspace_client.h"

#include <algorithm>
#include <future>
#include <std_srvs/Trigger.h>
#include <tf2_eigen/tf2_eigen.h>
#include <vrrw_msgs/GhostExecute.h>
#include <vrrw_msgs/GhostPlan.h>
#include <vrrw_msgs/GhostSetPose.h>
#include <vrrw_msgs/GhostSupportSurface.h>

namespace vrrw_evaluation
{
namespace
{
/// Longest ghost motion stepped (simulated s): a plan is bounded to 600 s, the demo's take a few.
constexpr double kLongestMotion = 600.0;
}  // namespace

GhostOperator::GhostOperator(ros::NodeHandle& node, const std::string& robot, vrrw_physics::LockstepClient& sim)
  : prefix_("/" + robot + "/ghost/"), self_(ros::this_node::getName() + "-"), sim_(sim)
{
  status_ = node.subscribe<actionlib_msgs::GoalStatusArray>(
      "/" + robot + "/arm_controller/follow_joint_trajectory/status", 100,
      [this](const actionlib_msgs::GoalStatusArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& goal : msg->status_list)  // taken (part of the simulation), and not this runner's own
          if (goal.status != actionlib_msgs::GoalStatus::PENDING && goal.goal_id.id.rfind(self_, 0) != 0)
            goals_.insert(goal.goal_id.id);
      });
}

bool GhostOperator::waitUntilReady(double seconds, std::string& error)
{
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  for (const char* name : { "reset", "clear_waypoints", "set_support_surface", "set_pose", "add_waypoint", "plan", "execute" })
  {
    const double left = std::max(0.01, (deadline - ros::WallTime::now()).toSec());
    if (!ros::service::waitForService(prefix_ + name, ros::Duration(left)))
      return error = "no interaction node (" + prefix_ + name + ")", false;
  }
  return true;
}

void GhostOperator::use(const std::string& service)
{
  if (std::find(used_.begin(), used_.end(), service) == used_.end())
    used_.push_back(service);
}

bool GhostOperator::trigger(const std::string& service, std::string& error)
{
  std_srvs::Trigger call;
  use(prefix_ + service);
  if (!links_.tryCall(prefix_ + service, call))
    return error = prefix_ + service + ": call failed", false;
  if (!call.response.success)
    return error = prefix_ + service + ": " + call.response.message, false;
  return true;
}

bool GhostOperator::setPose(const Eigen::Isometry3d& tcp, std::string& error)
{
  vrrw_msgs::GhostSetPose call;
  call.request.pose.header.frame_id = "world";
  call.request.pose.pose = tf2::toMsg(tcp);
  use(prefix_ + "set_pose");
  if (!links_.tryCall(prefix_ + "set_pose", call))
    return error = prefix_ + "set_pose: call failed", false;
  if (!call.response.success)
    return error = prefix_ + "set_pose: " + call.response.message, false;
  return true;
}

bool GhostOperator::drive(const std::vector<Eigen::Isometry3d>& waypoints, const Eigen::Isometry3d& goal,
                          std::string& error, double* plan_ms, const DriveOptions& options)
{
  // The ghost starts at the robot, so IK of each pose is the solution nearest the arm as it stands.
  if (!trigger("reset", error) || !trigger("clear_waypoints", error))
    return false;
  vrrw_msgs::GhostSupportSurface support;  // every drive says what it may set its held object down on
  support.request.name = options.support_surface;
  use(prefix_ + "set_support_surface");
  if (!links_.tryCall(prefix_ + "set_support_surface", support))
    return error = prefix_ + "set_support_surface: call failed", false;
  if (!support.response.success)
    return error = prefix_ + "set_support_surface: " + support.response.message, false;
  for (const Eigen::Isometry3d& waypoint : waypoints)
    if (!setPose(waypoint, error) || !trigger("add_waypoint", error))
      return false;
  if (!setPose(goal, error))
    return false;
  vrrw_msgs::GhostPlan plan;
  plan.request.max_velocity_scaling_factor = options.velocity_scaling;
  plan.request.max_acceleration_scaling_factor = options.acceleration_scaling;
  plan.request.time_profile = options.time_profile;
  use(prefix_ + "plan");
  const ros::WallTime start = ros::WallTime::now();
  if (!links_.tryCall(prefix_ + "plan", plan))
    return error = prefix_ + "plan: call failed", false;
  if (plan_ms)
    *plan_ms += (ros::WallTime::now() - start).toSec() * 1e3;
  if (!plan.response.success)
    return error = prefix_ + "plan: " + plan.response.message, false;
  return execute(error);
}

bool GhostOperator::execute(std::string& error)
{
  use(prefix_ + "execute");
  std::set<std::string> before;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    before = goals_;
  }
  auto taken = [&] {
    std::lock_guard<std::mutex> lock(mutex_);
    return goals_.size() > before.size();
  };
  vrrw_msgs::GhostExecute call;
  std::string why;
  auto answer = std::async(std::launch::async, [&] { return links_.tryCall(prefix_ + "execute", call, &why); });
  const auto answered = [&](double seconds) {
    return answer.wait_for(std::chrono::duration<double>(seconds)) == std::future_status::ready;
  };
  // Wait until the goal is in the controller (or the call ended without one: a refusal), then step.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kAnswerSeconds);
  while (!taken() && !answered(0.001) && ros::WallTime::now() < end)
    ;
  if (taken())
    sim_.stepUntilIdle(kLongestMotion);
  if (!answered(kAnswerSeconds) || !answer.get())
    return error = prefix_ + "execute: " + (why.empty() ? "no answer" : why), false;
  if (!call.response.success)
    return error = prefix_ + "execute: " + call.response.message + " " + call.response.error_string, false;
  return true;
}
}  // namespace vrrw_evaluation
