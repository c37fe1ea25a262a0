#pragma once
#include <map>
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>

namespace vrrw_demos
{
/// \brief What the recorder wrote on /demos/metadata (missing fields empty).
struct BagMetadata
{
  struct Robot
  {
    std::vector<std::string> arm_joints, gripper_joints;
    std::string base_link, tcp_link, config_file;
  };
  double start_stamp = 0.0;
  std::string scene, scene_file, scene_yaml, robot_description, vrrw_version, seed;
  std::vector<std::string> objects;
  std::map<std::string, Robot> robots;
};

constexpr const char* kMetadataTopic = "/demos/metadata";

/// \brief Reads the metadata of a bag (empty when it has none); throws DemoError "BAG: reason" when the
/// bag is unreadable (truncated, unindexed: the message says to recover it).
BagMetadata readMetadata(const std::string& bag);

/// \brief Reads the demonstration of \a robots (empty: every robot with a joint_states topic) from a bag:
/// /<robot>/joint_states (arm joints and gripper), gripper goals, /operator/events and /demos/events,
/// objects' poses from /tf. Throws DemoError naming the bag and the robot or topic.
Demonstration readDemonstration(const std::string& bag, const std::vector<std::string>& robots = {});

/// \brief Writes a new bag (never overwriting) holding \a track as /<robot>/joint_states stamped
/// start + t, and metadata naming its joints. Throws DemoError.
void writeTrackBag(const std::string& bag, const RobotTrack& track, const BagMetadata& metadata);
}  // namespace vrrw_demos
