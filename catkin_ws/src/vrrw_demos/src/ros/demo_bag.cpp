#include <vrrw_demos/ros/demo_bag.h>

#include <vrrw_common/joint_mapping.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

#include <control_msgs/GripperCommandActionGoal.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>
#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <vrrw_msgs/Event.h>
#include <yaml-cpp/yaml.h>

namespace vrrw_demos
{
namespace
{
void openBag(rosbag::Bag& bag, const std::string& path)
{
  struct stat info;
  if (::stat(path.c_str(), &info) != 0)
    throw DemoError(path + ": no such file");
  try
  {
    bag.open(path, rosbag::bagmode::Read);
  }
  catch (const rosbag::BagUnindexedException&)
  {
    throw DemoError(path + ": not indexed (the recording did not end cleanly): ./vrrw demos recover " + path);
  }
  catch (const rosbag::BagException& e)
  {
    throw DemoError(path + ": not a readable bag (" + std::string(e.what()) +
                    "); if it was cut short: ./vrrw demos recover " + path);
  }
}

std::vector<std::string> strings(const YAML::Node& node)
{
  std::vector<std::string> out;
  if (node && node.IsSequence())
    for (const auto& item : node)
      out.push_back(item.as<std::string>());
  return out;
}

std::string text(const YAML::Node& node)
{
  return node && node.IsScalar() ? node.as<std::string>() : "";
}

BagMetadata parseMetadata(const std::string& yaml, const std::string& source)
{
  BagMetadata metadata;
  try
  {
    const YAML::Node root = YAML::Load(yaml);
    metadata.start_stamp = root["start_sec"].as<double>(0.0) + 1e-9 * root["start_nsec"].as<double>(0.0);
    metadata.scene = text(root["scene"]);
    metadata.scene_file = text(root["scene_file"]);
    metadata.scene_yaml = text(root["scene_yaml"]);
    metadata.robot_description = text(root["robot_description"]);
    metadata.vrrw_version = text(root["vrrw_version"]);
    metadata.seed = text(root["seed"]);
    metadata.objects = strings(root["objects"]);
    if (root["robots"] && root["robots"].IsMap())
      for (const auto& entry : root["robots"])
      {
        BagMetadata::Robot& robot = metadata.robots[entry.first.as<std::string>()];
        robot.arm_joints = strings(entry.second["arm_joints"]);
        robot.gripper_joints = strings(entry.second["gripper_joints"]);
        robot.base_link = text(entry.second["base_link"]);
        robot.tcp_link = text(entry.second["tcp_link"]);
        robot.config_file = text(entry.second["config_file"]);
      }
  }
  catch (const YAML::Exception& e)
  {
    throw DemoError(source + ": " + kMetadataTopic + ": not valid metadata YAML (" + e.what() + ")");
  }
  return metadata;
}

BagMetadata metadataOf(rosbag::Bag& bag, const std::string& path)
{
  rosbag::View view(bag, rosbag::TopicQuery(kMetadataTopic));
  for (const rosbag::MessageInstance& message : view)
    if (const auto data = message.instantiate<std_msgs::String>())
      return parseMetadata(data->data, path);
  return {};
}

/// A bag without metadata (another recorder's) names no gripper joint: the grippers vrrw ships name theirs so.
bool looksLikeGripper(const std::string& joint)
{
  return joint.find("finger") != std::string::npos || joint.find("gripper") != std::string::npos;
}

/// The arm and gripper joints of a robot: from the metadata, else from its first joint_states message.
void jointsOf(RobotTrack& track, const BagMetadata& metadata, const sensor_msgs::JointState& first)
{
  const auto found = metadata.robots.find(track.robot);
  if (found != metadata.robots.end() && !found->second.arm_joints.empty())
  {
    track.joint_names = found->second.arm_joints;
    if (!found->second.gripper_joints.empty())
      track.gripper_joint = found->second.gripper_joints.front();
    return;
  }
  for (const std::string& name : first.name)
    if (!looksLikeGripper(name))
      track.joint_names.push_back(name);
    else if (track.gripper_joint.empty())
      track.gripper_joint = name;
}

/// Central differences where the bag had no velocities (one-sided at the ends).
void fillVelocities(RobotTrack& track, const std::vector<bool>& has_velocity)
{
  const std::size_t count = track.states.size();
  for (std::size_t k = 0; k < count; ++k)
  {
    if (has_velocity[k])
      continue;
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, count - 1);
    const double dt = track.states[b].time - track.states[a].time;
    track.states[k].velocities.assign(track.joint_names.size(), 0.0);
    for (std::size_t j = 0; dt > 0 && j < track.joint_names.size(); ++j)
      track.states[k].velocities[j] = (track.states[b].positions[j] - track.states[a].positions[j]) / dt;
  }
}

void readTrack(rosbag::Bag& bag, const std::string& path, const BagMetadata& metadata, double start,
               RobotTrack& track)
{
  const std::string topic = "/" + track.robot + "/joint_states";
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  std::vector<bool> has_velocity;
  double gripper = 0.0;
  for (const rosbag::MessageInstance& message : view)
  {
    const auto state = message.instantiate<sensor_msgs::JointState>();
    if (!state)
      throw DemoError(path + ": " + topic + " has " + message.getDataType() + ", expected sensor_msgs/JointState");
    if (track.joint_names.empty())
      jointsOf(track, metadata, *state);
    if (!track.gripper_joint.empty())
      if (const auto g = vrrw_common::findValues(state->name, state->position, { track.gripper_joint }))
        gripper = g->front();
    const auto positions = vrrw_common::findValues(state->name, state->position, track.joint_names);
    if (!positions)
      continue;  // another publisher's message (a gripper alone)
    RobotState sample;
    sample.time = (state->header.stamp.isZero() ? message.getTime() : state->header.stamp).toSec() - start;
    sample.gripper = gripper;
    sample.positions = *positions;
    const bool velocity = state->velocity.size() == state->name.size();
    if (velocity)
      sample.velocities = *vrrw_common::findValues(state->name, state->velocity, track.joint_names);
    if (!track.states.empty() && !(sample.time > track.states.back().time))
      continue;  // a repeated stamp: the same state published twice
    has_velocity.push_back(velocity);
    track.states.push_back(std::move(sample));
  }
  if (track.states.empty())
    throw DemoError(path + ": " + topic + ": no joint_states with the arm joints of robot '" + track.robot + "'");
  fillVelocities(track, has_velocity);

  rosbag::View goals(bag, rosbag::TopicQuery("/" + track.robot + "/gripper_controller/gripper_cmd/goal"));
  // a goal's time: when it was sent (its stamp), not when it happened to reach the recorder
  for (const rosbag::MessageInstance& message : goals)
    if (const auto goal = message.instantiate<control_msgs::GripperCommandActionGoal>())
      track.gripper_goals.push_back({ (goal->header.stamp.isZero() ? message.getTime() : goal->header.stamp).toSec() -
                                          start,
                                      goal->goal.command.position, goal->goal.command.max_effort });
}
}  // namespace

BagMetadata readMetadata(const std::string& path)
{
  rosbag::Bag bag;
  openBag(bag, path);
  return metadataOf(bag, path);
}

Demonstration readDemonstration(const std::string& path, const std::vector<std::string>& robots)
{
  rosbag::Bag bag;
  openBag(bag, path);
  Demonstration demo;
  demo.source = path;
  demo.metadata = metadataOf(bag, path);
  const BagMetadata& metadata = demo.metadata;
  rosbag::View all(bag);
  // time 0 of every track, event and pose: the recorder's start, or the bag's first message without metadata
  demo.start_stamp = metadata.start_stamp > 0 ? metadata.start_stamp : all.getBeginTime().toSec();

  // The robots: every /<robot>/joint_states in the bag (or those asked for), each read into its track.

  std::set<std::string> found;
  const std::regex states("/([^/]+)/joint_states");
  for (const rosbag::ConnectionInfo* connection : all.getConnections())
  {
    std::smatch match;
    if (std::regex_match(connection->topic, match, states))
      found.insert(match[1]);
  }
  std::vector<std::string> wanted = robots.empty() ? std::vector<std::string>(found.begin(), found.end()) : robots;
  if (wanted.empty())
    throw DemoError(path + ": no /<robot>/joint_states topic: not a demonstration bag");
  for (const std::string& robot : wanted)
  {
    if (!found.count(robot))
      throw DemoError(path + ": no robot '" + robot + "' (no topic /" + robot + "/joint_states; the bag has: " +
                      [&] { std::string list; for (const auto& r : found) list += (list.empty() ? "" : ", ") + r;
                            return list.empty() ? std::string("none") : list; }() + ")");
    demo.robots.push_back({});
    demo.robots.back().robot = robot;
    readTrack(bag, path, metadata, demo.start_stamp, demo.robots.back());
  }

  // The operator's and the annotations' events, at their own stamps (the receipt time when unstamped).
  rosbag::View events(bag, rosbag::TopicQuery(std::vector<std::string>{ "/operator/events", "/demos/events" }));
  for (const rosbag::MessageInstance& message : events)
    if (const auto event = message.instantiate<vrrw_msgs::Event>())
      demo.events.push_back({ (event->header.stamp.isZero() ? message.getTime() : event->header.stamp).toSec() -
                                  demo.start_stamp, event->robot, event->kind, event->detail });

  // The objects' poses from the recorded tf: the metadata's objects, or (no metadata) every frame under world.
  const std::set<std::string> objects(metadata.objects.begin(), metadata.objects.end());
  rosbag::View tf(bag, rosbag::TopicQuery(std::vector<std::string>{ "/tf", "/tf_static" }));
  for (const rosbag::MessageInstance& message : tf)
    if (const auto transforms = message.instantiate<tf2_msgs::TFMessage>())
      for (const auto& transform : transforms->transforms)
      {
        if (objects.empty() ? transform.header.frame_id != "world" : !objects.count(transform.child_frame_id))
          continue;
        TimedPose pose;
        pose.time = (transform.header.stamp.isZero() ? message.getTime() : transform.header.stamp).toSec() -
                    demo.start_stamp;
        const auto& t = transform.transform.translation;
        const auto& r = transform.transform.rotation;
        pose.pose = Pose{ { t.x, t.y, t.z }, { r.x, r.y, r.z, r.w } };
        demo.objects[transform.child_frame_id].push_back(pose);
      }
  // in time order (objectPoseAt searches them): /tf and /tf_static may interleave
  for (auto& entry : demo.objects)
    std::stable_sort(entry.second.begin(), entry.second.end(),
                     [](const TimedPose& a, const TimedPose& b) { return a.time < b.time; });
  return demo;
}

void writeTrackBag(const std::string& path, const RobotTrack& track, const BagMetadata& metadata)
{
  refuseTaken(path);  // nor a recording's FILE.active: the bag is written beside it and linked when whole
  const std::string temporary = temporaryBeside(path);
  const ros::Time start = ros::Time().fromSec(metadata.start_stamp);
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "format" << YAML::Value << "vrrw_demos/1";
  out << YAML::Key << "start_sec" << YAML::Value << start.sec << YAML::Key << "start_nsec" << YAML::Value
      << start.nsec;
  out << YAML::Key << "robots" << YAML::Value << YAML::BeginMap << YAML::Key << track.robot << YAML::Value
      << YAML::BeginMap << YAML::Key << "arm_joints" << YAML::Value << YAML::Flow << track.joint_names;
  out << YAML::Key << "gripper_joints" << YAML::Value << YAML::Flow
      << (track.gripper_joint.empty() ? std::vector<std::string>{} : std::vector<std::string>{ track.gripper_joint });
  out << YAML::EndMap << YAML::EndMap << YAML::EndMap;
  try
  {
    rosbag::Bag bag(temporary, rosbag::bagmode::Write);
    std_msgs::String text;
    text.data = out.c_str();
    bag.write(kMetadataTopic, start, text);
    for (const RobotState& state : track.states)
    {
      sensor_msgs::JointState message;
      message.header.stamp = start + ros::Duration().fromSec(state.time);
      message.name = track.joint_names;
      message.position = state.positions;
      message.velocity = state.velocities;
      if (!track.gripper_joint.empty())
      {
        message.name.push_back(track.gripper_joint);
        message.position.push_back(state.gripper);
        message.velocity.push_back(0.0);
      }
      bag.write("/" + track.robot + "/joint_states", message.header.stamp, message);
    }
    bag.close();
  }
  catch (const rosbag::BagException& e)
  {
    ::unlink(temporary.c_str());
    throw DemoError(path + ": cannot write (" + std::string(e.what()) + ")");
  }
  publishNewFile(temporary, path);
}
}  // namespace vrrw_demos
