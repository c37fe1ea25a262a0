#include "demo_recorder.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

#include <vrrw_demos/demo_error.h>
#include <vrrw_demos/new_file.h>
#include <vrrw_common/run_program.h>
#include <vrrw_msgs/DemoStatus.h>
#include <vrrw_msgs/Event.h>
#include <vrrw_scene/scene_loader.h>
#include <yaml-cpp/yaml.h>

namespace vrrw_demos
{
namespace
{
std::string readText(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string vrrwVersion()
{
  std::string version;
  vrrw_common::runProgram({ "git", "-C", vrrw_scene::vrrwRoot(), "describe", "--always", "--dirty", "--tags" },
                          &version, true);
  while (!version.empty() && (version.back() == '\n' || version.back() == ' '))
    version.pop_back();
  return version.empty() ? "unknown" : version;
}

std::vector<std::string> sceneRobots(ros::NodeHandle& nh)
{
  XmlRpc::XmlRpcValue robots;
  std::vector<std::string> names;
  if (nh.getParam("/scene/robots", robots) && robots.getType() == XmlRpc::XmlRpcValue::TypeStruct)
    for (const auto& entry : robots)
      names.push_back(entry.first);
  return names;
}

std::string joined(const std::vector<std::string>& names)
{
  std::string text;
  for (const std::string& name : names)
    text += (text.empty() ? "" : ", ") + name;
  return text;
}

/// The bag's own description: scene YAML, combined URDF, version, seed, robots' joints and links.
std::string metadataYaml(ros::NodeHandle& nh, const std::vector<std::string>& robots, const ros::Time& start)
{
  const std::string scene_file = nh.param<std::string>("/scene/file", "");
  const std::string scene_yaml = scene_file.empty() ? "" : readText(scene_file);
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "vrrw_demos/1";
  out << YAML::Key << "start_sec" << YAML::Value << start.sec;
  out << YAML::Key << "start_nsec" << YAML::Value << start.nsec;
  out << YAML::Key << "vrrw_version" << YAML::Value << vrrwVersion();
  out << YAML::Key << "scene" << YAML::Value << nh.param<std::string>("/scene/name", "");
  out << YAML::Key << "scene_file" << YAML::Value << scene_file;
  YAML::Node scene;
  try
  {
    scene = YAML::Load(scene_yaml);
  }
  catch (const YAML::Exception&)
  {
    // a scene file that does not parse has no seed and no objects to name; its text is still kept below
  }
  out << YAML::Key << "seed" << YAML::Value << (scene["seed"] ? scene["seed"].as<std::string>() : "none");
  out << YAML::Key << "objects" << YAML::Value << YAML::BeginSeq;
  if (scene["objects"] && scene["objects"].IsSequence())
    for (const auto& object : scene["objects"])
      if (object["name"])
        out << object["name"].as<std::string>();
  out << YAML::EndSeq;
  out << YAML::Key << "robots" << YAML::Value << YAML::BeginMap;
  for (const std::string& robot : robots)
  {
    const std::string key = "/scene/robots/" + robot + "/";
    out << YAML::Key << robot << YAML::Value << YAML::BeginMap;
    for (const char* list : { "arm_joints", "gripper_joints" })
      out << YAML::Key << list << YAML::Value << YAML::Flow << nh.param(key + list, std::vector<std::string>{});
    for (const char* field : { "model", "gripper", "base_link", "tcp_link", "config_file" })
      out << YAML::Key << field << YAML::Value << nh.param<std::string>(key + field, "");
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  out << YAML::Key << "scene_yaml" << YAML::Value << YAML::Literal << scene_yaml;
  out << YAML::Key << "robot_description" << YAML::Value << YAML::Literal
      << nh.param<std::string>("/robot_description", "");
  out << YAML::EndMap;
  return out.c_str();
}
}  // namespace

DemoRecorder::DemoRecorder(ros::NodeHandle nh, const std::string& file, const std::vector<std::string>& robots)
  : nh_(nh), recorder_(nh)
{
  events_ = nh.advertise<vrrw_msgs::Event>("/demos/events", 100);
  status_ = nh.advertise<vrrw_msgs::DemoStatus>("/demos/status", 1, true);
  services_.push_back(nh.advertiseService("/demos/start", &DemoRecorder::onStart, this));
  services_.push_back(nh.advertiseService("/demos/stop", &DemoRecorder::onStop, this));
  services_.push_back(nh.advertiseService("/demos/annotate", &DemoRecorder::onAnnotate, this));
  poll_timer_ = nh.createWallTimer(ros::WallDuration(kPollPeriod), [this](const ros::WallTimerEvent&) { poll(); });
  status_timer_ = nh.createWallTimer(ros::WallDuration(kStatusPeriod), [this](const ros::WallTimerEvent&) {
    if (recorder_.recording())
      publishStatus();
  });
  publishStatus();
  if (file.empty())
    return;
  try
  {
    start(file, robots);
  }
  catch (const DemoError& e)
  {
    ROS_ERROR_STREAM("recorder: " << e.what());
  }
}

void DemoRecorder::shutdown()
{
  if (!recorder_.recording())
    return;
  try
  {
    const uint64_t messages = recorder_.stop();
    ROS_INFO_STREAM("recorder: " << recorder_.status().file << ": " << messages << " messages");
  }
  catch (const DemoError& e)
  {
    ROS_ERROR_STREAM("recorder: " << e.what());
  }
}

void DemoRecorder::start(const std::string& file, std::vector<std::string> robots)
{
  const std::vector<std::string> scene = sceneRobots(nh_);
  if (scene.empty())
    throw DemoError("robots: no scene is up (/scene/robots is empty): start one with ./vrrw up SCENE");
  if (robots.empty())
    robots = scene;
  for (const std::string& robot : robots)
    if (std::find(scene.begin(), scene.end(), robot) == scene.end())
      throw DemoError("robots: '" + robot + "' is not a robot of the scene (its robots: " + joined(scene) + ")");
  recorder_.start(file, robots, metadataYaml(nh_, robots, ros::Time::now()));
  const auto status = recorder_.status();
  ROS_INFO_STREAM("recorder: recording " << joined(robots) << " to " << file << " (" << status.topics.size()
                                         << " topics)");
  if (!status.incomplete.empty())
    ROS_WARN_STREAM("recorder: " << status.incomplete);
  publishStatus();
}

void DemoRecorder::poll()
{
  recorder_.subscribeNewTopics();
  const std::string failure = recorder_.takeFailure();
  if (!failure.empty())
  {
    ROS_ERROR_STREAM("recorder: " << failure);
    publishStatus();
  }
}

void DemoRecorder::publishStatus()
{
  const auto status = recorder_.status();
  vrrw_msgs::DemoStatus message;
  message.recording = status.recording;
  message.file = status.file;
  message.robots = status.robots;
  message.topics = status.topics;
  message.started = status.started;
  message.complete_from = status.complete_from;
  message.messages = status.messages;
  struct stat info;
  const std::string& on_disk = status.recording ? status.active_file : status.file;
  message.bytes = !on_disk.empty() && ::stat(on_disk.c_str(), &info) == 0 ? static_cast<uint64_t>(info.st_size) : 0;
  message.failure = status.failure;
  status_.publish(message);
}

bool DemoRecorder::onStart(vrrw_msgs::DemoStart::Request& request, vrrw_msgs::DemoStart::Response& response)
{
  char* absolute = ::realpath(".", nullptr);  // a relative file is the recorder's working directory's
  std::string file = request.file;
  if (!file.empty() && file[0] != '/' && absolute)
    file = std::string(absolute) + "/" + file;
  std::free(absolute);
  try
  {
    start(file, request.robots);
  }
  catch (const DemoError& e)
  {
    response.success = false;
    response.message = e.what();
    return true;
  }
  const auto status = recorder_.status();
  response.success = true;
  response.file = file;
  response.topics = status.topics;
  response.complete_from = status.complete_from;
  response.message = "recording " + joined(status.robots) + " to " + file + ": " +
                     std::to_string(status.topics.size()) + " topics, complete from " +
                     std::to_string(status.complete_from.toSec()) + " s (ROS time: simulated in physics)" +
                     (status.incomplete.empty() ? "" : "; " + status.incomplete);
  return true;
}

bool DemoRecorder::onStop(vrrw_msgs::DemoStop::Request&, vrrw_msgs::DemoStop::Response& response)
{
  if (!recorder_.recording())
  {
    response.success = false;
    response.message = "not recording";
    return true;
  }
  try
  {
    response.messages = recorder_.stop();
    response.file = recorder_.status().file;
    response.success = true;
    response.message = std::to_string(response.messages) + " messages in " + response.file;
  }
  catch (const DemoError& e)
  {
    const auto status = recorder_.status();
    response.success = false;
    response.message = e.what();
    response.file = status.active_file;  // where the data stays
    response.messages = status.messages;
    ROS_ERROR_STREAM("recorder: " << response.message);
  }
  publishStatus();
  return true;
}

bool DemoRecorder::onAnnotate(vrrw_msgs::DemoAnnotate::Request& request, vrrw_msgs::DemoAnnotate::Response& response)
{
  vrrw_msgs::Event event;
  event.header.stamp = request.stamp.isZero() ? ros::Time::now() : request.stamp;
  event.source = "demos";
  event.kind = "annotate";
  event.detail = request.text;
  events_.publish(event);
  response.success = recorder_.recording();
  response.message = response.success ? "annotated" : "published on /demos/events, but no recording is running";
  return true;
}
}  // namespace vrrw_demos
