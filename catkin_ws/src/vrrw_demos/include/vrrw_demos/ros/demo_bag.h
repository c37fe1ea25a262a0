#pragma once
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>

namespace vrrw_demos
{
constexpr const char* kMetadataTopic = "/demos/metadata";

/// \brief Reads the metadata of a bag (empty when it has none); throws DemoError "BAG: reason" when the
/// bag is unreadable (truncated, unindexed: the message says to recover it).
BagMetadata readMetadata(const std::string& bag);

/// \brief Reads the demonstration of \a robots (empty: every robot with a joint_states topic) from a bag:
/// its metadata, /<robot>/joint_states (arm joints and gripper), gripper goals (position and max_effort),
/// /operator/events and /demos/events, objects' poses from /tf. Every package reads bags through this.
/// Throws DemoError naming the bag and the robot or topic (a bag cut short: `./vrrw demos recover`).
Demonstration readDemonstration(const std::string& bag, const std::vector<std::string>& robots = {});

/// \brief Writes a new bag (never overwriting) holding \a track as /<robot>/joint_states stamped
/// start + t, and metadata naming its joints. Throws DemoError.
void writeTrackBag(const std::string& bag, const RobotTrack& track, const BagMetadata& metadata);
}  // namespace vrrw_demos
