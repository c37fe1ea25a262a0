#pragma once
// The demo's service calls, each over a persistent connection. A one-shot roscpp call opens a connection,
// and the server closes it after answering; roscpp 1.15 may take that close for a dead link before it has
// read the answer (ros_comm#1976, POLLRDHUP) and report "call failed" for a call the node carried out.
// A persistent connection is never closed by the server.
#include <map>
#include <ros/ros.h>
#include <string>

namespace vrrw_evaluation
{
class ServiceLinks
{
public:
  /// \brief Calls `name` over its connection (opened at the first call, reopened after a drop); false when
  /// no answer came back. From one thread (the runner calls from its main thread).
  template <class Service>
  bool call(const std::string& name, Service& srv)
  {
    ros::ServiceClient& client = clients_[name];
    if (!client.isValid())
      client = ros::NodeHandle().serviceClient<Service>(name, true);
    if (client.call(srv))
      return true;
    client.shutdown();
    return false;
  }

private:
  std::map<std::string, ros::ServiceClient> clients_;
};
}  // namespace vrrw_evaluation
