#include "vrrw_common/ros/workspace_check.h"

#include <algorithm>
#include <future>
#include <memory>
#include <ros/ros.h>
#include <thread>
#include <xmlrpcpp/XmlRpcClient.h>

namespace vrrw_common
{
bool masterAnswers(double seconds)
{
  // An XML-RPC call has no time limit of its own (a stopped master holds it): ask on a thread of its own with
  // a client of its own (not roscpp's, which shutdown would free under it), and leave that thread behind if
  // it does not come back in time.
  auto answered = std::make_shared<std::promise<bool>>();
  auto result = answered->get_future();
  std::thread([answered, host = ros::master::getHost(), port = ros::master::getPort()] {
    XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
    XmlRpc::XmlRpcValue request, response;
    request[0] = "vrrw_workspace_check";
    answered->set_value(client.execute("getPid", request, response) && response.valid());
  }).detach();
  return result.wait_for(std::chrono::duration<double>(seconds)) == std::future_status::ready && result.get();
}

std::vector<std::string> workspaceRobots()
{
  std::vector<std::string> robots;
  XmlRpc::XmlRpcValue scene_robots;
  if (ros::param::get("/scene/robots", scene_robots) && scene_robots.getType() == XmlRpc::XmlRpcValue::TypeStruct)
    for (const auto& robot : scene_robots)
      robots.push_back(robot.first);
  std::sort(robots.begin(), robots.end());
  return robots;
}

namespace
{
std::string joined(const std::vector<std::string>& names)
{
  std::string text;
  for (const auto& name : names)
    text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

void checkRobot(const std::string& robot)
{
  if (ros::param::has("/scene/robots/" + robot + "/arm_joints"))
    return;
  const auto robots = workspaceRobots();
  if (robots.empty())
    throw WorkspaceError("no workspace at " + ros::master::getURI() +
                         ": a master runs but no scene is up (/scene/robots): start one with ./vrrw up SCENE");
  throw WorkspaceError("robot '" + robot + "' is not in the running workspace (its robots: " + joined(robots) + ")");
}

void checkActions(const std::vector<std::string>& actions)
{
  if (actions.empty())
    return;
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics))
    throw WorkspaceError("no workspace at " + ros::master::getURI() + ": the master stopped answering");
  for (const auto& action : actions)
  {
    const bool found = std::any_of(topics.begin(), topics.end(),
                                   [&](const ros::master::TopicInfo& t) { return t.name == action + "/status"; });
    if (!found)
      throw WorkspaceError("no controller at " + action +
                           " in the running workspace (is it up with --mode fake or physics?)");
  }
}

void checkServices(const std::vector<std::string>& services)
{
  for (const auto& service : services)
    if (!ros::service::exists(service, false))
      throw WorkspaceError("no service " + service + " in the running workspace");
}
}  // namespace

void checkWorkspace(const WorkspaceNeeds& needs, double master_seconds)
{
  if (!masterAnswers(master_seconds))
    throw WorkspaceError("no workspace at " + ros::master::getURI() + ": start one with ./vrrw up SCENE");
  if (!needs.robot.empty())
    checkRobot(needs.robot);
  checkActions(needs.actions);
  checkServices(needs.services);
}
}  // namespace vrrw_common
