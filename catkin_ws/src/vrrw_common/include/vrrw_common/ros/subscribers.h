#pragma once
#include <string>

namespace vrrw_common
{
/// \brief Waits (wall clock, at most \a seconds) until every node the master lists as a subscriber of \a topic is
/// connected to this process's publisher of it, and says whether all are. A message published before a
/// subscriber connects never reaches it: a short-lived tool's only goal was missing from a recording that way.
bool waitForSubscribers(const std::string& topic, double seconds);
}  // namespace vrrw_common
