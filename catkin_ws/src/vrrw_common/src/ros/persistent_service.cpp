#include "vrrw_common/ros/persistent_service.h"

#include <sstream>

namespace vrrw_common
{
bool PersistentServices::waitFor(const std::string& name, double seconds)
{
  return ros::service::waitForService(name, ros::Duration(seconds));
}

void PersistentServices::drop(const std::string& name, ros::ServiceClient& client)
{
  client.shutdown();
  std::lock_guard<std::mutex> lock(mutex_);
  clients_.erase(name);
}

PersistentServices& services()
{
  // Never destroyed: its clients must not be shut down after roscpp itself at exit.
  static auto* shared = new PersistentServices();
  return *shared;
}

std::string PersistentServices::seconds(double value)
{
  std::ostringstream out;
  out << value << " s";
  return out.str();
}
}  // namespace vrrw_common
