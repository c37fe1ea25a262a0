#include <vrrw_common/ros/subscribers.h>

#include <ros/master.h>
#include <ros/ros.h>
#include <ros/topic_manager.h>

namespace vrrw_common
{
namespace
{
/// The nodes other than this one that the master lists as subscribers of \a topic (0 when it does not answer).
int listedSubscribers(const std::string& topic)
{
  XmlRpc::XmlRpcValue args, result, state;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, state, false) || state.getType() != XmlRpc::XmlRpcValue::TypeArray)
    return 0;
  XmlRpc::XmlRpcValue& subscribed = state[1];  // [[topic, [node, ...]], ...]
  for (int i = 0; i < subscribed.size(); ++i)
    if (static_cast<std::string>(subscribed[i][0]) == topic)
    {
      int others = 0;
      for (int k = 0; k < subscribed[i][1].size(); ++k)
        others += static_cast<std::string>(subscribed[i][1][k]) != ros::this_node::getName() ? 1 : 0;
      return others;
    }
  return 0;
}
}  // namespace

bool waitForSubscribers(const std::string& topic, double seconds)
{
  const std::string name = ros::names::resolve(topic);
  const int listed = listedSubscribers(name);
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);; ros::WallDuration(0.005).sleep())
  {
    if (int(ros::TopicManager::instance()->getNumSubscribers(name)) >= listed)
      return true;
    if (ros::WallTime::now() > end || !ros::ok())
      return false;
  }
}
}  // namespace vrrw_common
