#pragma once
// The one way to call a ROS service: over a persistent connection per name. A one-shot roscpp call opens a
// connection that the server closes after answering; roscpp 1.15 may take that close for a dead link before
// it has read the answer (ros_comm#1976, POLLRDHUP) and report a failure for a call the server carried out.
// A persistent connection is never closed by the server, so its answer cannot be lost that way.
#include <future>
#include <map>
#include <mutex>
#include <ros/ros.h>
#include <stdexcept>
#include <string>

namespace vrrw_common
{
/// \brief A service call that did not come back; what() is one line naming the service.
class ServiceError : public std::runtime_error
{
public:
  explicit ServiceError(const std::string& what) : std::runtime_error(what) {}
};

/// \brief How long a call may take in all.
struct ServiceLimits
{
  double wait_seconds = 5.0;   ///< for the service to be advertised before the first call (or after a drop)
  double call_seconds = 60.0;  ///< for its answer (a plan takes seconds; nothing we call takes a minute)
};

/// \brief Calls of ROS services, one persistent ServiceClient per name, opened at its first call and
/// reopened after its server went away. Safe from several threads (calls of one name queue on its link).
class PersistentServices
{
public:
  explicit PersistentServices(const ServiceLimits& limits = ServiceLimits(), ros::NodeHandle node = ros::NodeHandle())
    : limits_(limits), node_(node)
  {
  }

  /// \brief Calls \a name with \a srv; throws ServiceError (`/ur5e/plan: no such service after 5 s`,
  /// `/ur5e/plan: no answer within 60 s`, `/ur5e/plan: the call failed ...`). The answer's own success
  /// field is the caller's to read.
  template <class Service>
  void call(const std::string& name, Service& srv)
  {
    call(name, srv, limits_.call_seconds);
  }
  /// \brief The same with a call time of its own (e.g. a plan with a long time limit).
  template <class Service>
  void call(const std::string& name, Service& srv, double call_seconds)
  {
    ros::ServiceClient client = link<Service>(name);
    // A call runs on its own thread so that a server that never answers cannot hold the caller: after the
    // bound the link is shut down, which ends the call (roscpp cancels calls on a dropped link).
    auto answer = std::async(std::launch::async, [&client, &srv] { return client.call(srv); });
    if (answer.wait_for(std::chrono::duration<double>(call_seconds)) != std::future_status::ready)
    {
      drop(name, client);
      answer.wait();
      throw ServiceError(name + ": no answer within " + seconds(call_seconds));
    }
    if (!answer.get())
    {
      drop(name, client);
      throw ServiceError(name + ": the call failed (the server refused it or went away)");
    }
  }
  /// \brief call() returning false instead of throwing (for a caller that only reports the failure).
  template <class Service>
  bool tryCall(const std::string& name, Service& srv, std::string* error = nullptr)
  {
    try
    {
      call(name, srv);
      return true;
    }
    catch (const ServiceError& e)
    {
      if (error)
        *error = e.what();
      return false;
    }
  }

  /// \brief Waits up to \a seconds for \a name to be advertised; false when it is not.
  static bool waitFor(const std::string& name, double seconds);

private:
  /// The open link to \a name, opened (after waiting for the service) when there is none or it dropped.
  template <class Service>
  ros::ServiceClient link(const std::string& name)
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto found = clients_.find(name);
      if (found != clients_.end() && found->second.isValid())
        return found->second;
    }
    if (!waitFor(name, limits_.wait_seconds))
      throw ServiceError(name + ": no such service after " + seconds(limits_.wait_seconds) +
                         " (is the workspace up? ./vrrw up SCENE)");
    std::lock_guard<std::mutex> lock(mutex_);
    auto& client = clients_[name];
    if (!client.isValid())
      client = node_.serviceClient<Service>(name, true);
    return client;
  }
  void drop(const std::string& name, ros::ServiceClient& client);
  static std::string seconds(double value);

  const ServiceLimits limits_;
  ros::NodeHandle node_;
  std::mutex mutex_;                                  ///< protects clients_
  std::map<std::string, ros::ServiceClient> clients_;  ///< PROTECTED BY mutex_
};

/// \brief The process's own PersistentServices with the default limits, for code that keeps no set of its own
/// (tools, tests): `vrrw_common::services().call("/physics/reset", reset)`.
PersistentServices& services();
}  // namespace vrrw_common
