#pragma once
#include <ros/time.h>

namespace vrrw_interaction
{
/// \brief When an observer's copy of the ghost goes out again at a state's instant (WorldView::onInstant): when
/// it changed since the last send, or a second after it (the keepalive). The instants are the stamps of the
/// states taken, so a lockstep simulation gets the same sends at the same stamps however fast it runs.
class SendSchedule
{
public:
  /// s: a late subscriber, a recorder or rviz gets the ghost while nothing moves
  static constexpr double kKeepalive = 1.0;
  /// s: at most one send per 15 ms of ROS time: every state of a 50 Hz stream (20 ms apart), never the 200 Hz of
  /// four fake controllers' streams, each of whose states is an instant of its own
  static constexpr double kMinGap = 0.015;

  /// \brief Whether to send at `at`, the ghost `changed` since the last send.
  bool due(const ros::Time& at, bool changed) const
  {
    if (last_.isZero() || at + ros::Duration(kKeepalive) < last_)  // never sent, or the clock went back (a reset)
      return true;
    const double since = (at - last_).toSec();
    return since >= kKeepalive - kRounding || (changed && since >= kMinGap);
  }
  void sent(const ros::Time& at) { last_ = at; }
  const ros::Time& last() const { return last_; }

private:
  /// s: simulated time is a sum of 1 ms steps in double: a stamp may lie a nanosecond off its grid
  static constexpr double kRounding = 1e-6;
  ros::Time last_;
};
}  // namespace vrrw_interaction
