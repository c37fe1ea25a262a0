#include <vrrw_common/ros/topic_graph.h>

#include <ros/master.h>
#include <ros/ros.h>
#include <ros/topic_manager.h>

#include <algorithm>

namespace vrrw_common
{
namespace
{
/// [[topic, [node, ...]], ...] as a map.
std::map<std::string, std::vector<std::string>> nodesByTopic(XmlRpc::XmlRpcValue& list)
{
  std::map<std::string, std::vector<std::string>> nodes;
  for (int i = 0; i < list.size(); ++i)
  {
    std::vector<std::string>& of = nodes[static_cast<std::string>(list[i][0])];
    for (int k = 0; k < list[i][1].size(); ++k)
      of.push_back(static_cast<std::string>(list[i][1][k]));
  }
  return nodes;
}
}  // namespace

std::optional<TopicGraph> topicGraph()
{
  XmlRpc::XmlRpcValue args, result, state;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, state, false) ||
      state.getType() != XmlRpc::XmlRpcValue::TypeArray || state.size() < 2)
    return std::nullopt;
  return TopicGraph{ nodesByTopic(state[0]), nodesByTopic(state[1]) };  // (state[2]: the services)
}

bool waitForSubscribers(const std::string& topic, double seconds)
{
  const std::string name = ros::names::resolve(topic);
  int listed = 0;  // the subscribers other than this node
  if (const auto graph = topicGraph(); graph && graph->subscribers.count(name))
  {
    const std::vector<std::string>& nodes = graph->subscribers.at(name);
    listed = int(nodes.size()) - int(std::count(nodes.begin(), nodes.end(), ros::this_node::getName()));
  }
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);; ros::WallDuration(0.005).sleep())
  {
    if (int(ros::TopicManager::instance()->getNumSubscribers(name)) >= listed)
      return true;
    if (ros::WallTime::now() > end || !ros::ok())
      return false;
  }
}
}  // namespace vrrw_common
