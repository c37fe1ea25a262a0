#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vrrw_common
{
/// \brief Who publishes and who subscribes which topic, as the master has it (its getSystemState).
struct TopicGraph
{
  std::map<std::string, std::vector<std::string>> publishers, subscribers;  ///< topic -> node names
};

/// \brief The master's topic graph; nullopt when it does not answer.
std::optional<TopicGraph> topicGraph();

/// \brief Waits (wall clock, at most \a seconds) until every node the master lists as a subscriber of \a topic is
/// connected to this process's publisher of it, and says whether all are. A message published before a
/// subscriber connects never reaches it: a short-lived tool's only goal was missing from a recording that way.
bool waitForSubscribers(const std::string& topic, double seconds);
}  // namespace vrrw_common
