#include <vrrw_physics/ros/lockstep_client.h>

#include <std_srvs/Empty.h>
#include <vrrw_physics/Step.h>

#include <algorithm>

namespace vrrw_physics
{
namespace
{
/// Longest wait for one step call: a slice at rtf 1 takes its own length; a loaded machine may take many times it.
constexpr double kCallSeconds = 120.0;
}  // namespace

LockstepClient::LockstepClient(vrrw_common::PersistentServices& services, const std::string& physics,
                               const LockstepOptions& options)
  : services_(services), physics_(physics), options_(options)
{
}

bool LockstepClient::waitForPhysics(double seconds) const
{
  return vrrw_common::PersistentServices::waitFor(physics_ + "/step", seconds);
}

void LockstepClient::pause()
{
  std_srvs::Empty srv;
  try
  {
    services_.call(physics_ + "/pause", srv);
  }
  catch (const vrrw_common::ServiceError& e)
  {
    throw LockstepError(e.what());
  }
  now();
}

void LockstepClient::unpause()
{
  std_srvs::Empty srv;
  try
  {
    services_.call(physics_ + "/unpause", srv);
  }
  catch (const vrrw_common::ServiceError& e)
  {
    throw LockstepError(e.what());
  }
}

int LockstepClient::addStopObserver(StopObserver observer)
{
  observers_.emplace_back(next_key_, std::move(observer));
  return next_key_++;
}

void LockstepClient::removeStopObserver(int key)
{
  observers_.erase(std::remove_if(observers_.begin(), observers_.end(), [key](const auto& o) { return o.first == key; }),
                   observers_.end());
}

ros::Time LockstepClient::now()
{
  call(0.0, false);
  return time_;
}

ros::Time LockstepClient::step(double seconds)
{
  for (double left = seconds; left > 0.0; left -= options_.slice)
    call(std::min(left, options_.slice), false);
  return time_;
}

bool LockstepClient::stepUntilIdle(double seconds)
{
  double left = seconds;
  do
  {
    if (call(std::min(left, options_.slice), true))
      return true;
    left -= options_.slice;
  } while (left > 0.0);
  return false;
}

bool LockstepClient::paused()
{
  vrrw_physics::Step srv;
  try
  {
    services_.call(physics_ + "/step", srv, kCallSeconds);
  }
  catch (const vrrw_common::ServiceError& e)
  {
    throw LockstepError(e.what());
  }
  if (srv.response.success)
    return time_ = srv.response.time, true;
  if (srv.response.message.find("the simulation runs") != std::string::npos)
    return false;
  throw LockstepError(physics_ + "/step: " + srv.response.message);
}

bool LockstepClient::call(double seconds, bool until_idle)
{
  vrrw_physics::Step srv;
  srv.request.duration = seconds;
  srv.request.until_idle = until_idle;
  srv.request.rtf = options_.rtf;
  const std::string name = physics_ + "/step";
  try
  {
    services_.call(name, srv, kCallSeconds);
  }
  catch (const vrrw_common::ServiceError& e)
  {
    throw LockstepError(e.what());
  }
  if (!srv.response.success)
    throw LockstepError(name + ": " + srv.response.message);
  time_ = srv.response.time;
  if (srv.response.steps > 0)
    for (const auto& observer : observers_)
      observer.second(time_);
  return srv.response.idle;
}
}  // namespace vrrw_physics
