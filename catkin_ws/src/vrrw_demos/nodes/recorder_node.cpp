// recorder_node: records demonstrations to rosbag (BagRecorder).
//   services /demos/start (vrrw_msgs/DemoStart), /demos/stop (DemoStop), /demos/annotate (DemoAnnotate)
//   publishes /demos/events (vrrw_msgs/Event: annotations; recorded like every other event)
//   params ~file (start recording to it at once), ~robots (list; default all the scene's robots)
#include <cstdio>
#include <fstream>
#include <sstream>

#include <ros/ros.h>
#include <vrrw_msgs/DemoAnnotate.h>
#include <vrrw_msgs/DemoStart.h>
#include <vrrw_msgs/DemoStop.h>
#include <vrrw_msgs/Event.h>
#include <vrrw_scene/scene_loader.h>
#include <yaml-cpp/yaml.h>

#include "bag_recorder.h"

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
  const std::string command = "git -C '" + vrrw_scene::vrrwRoot() + "' describe --always --dirty --tags 2>/dev/null";
  std::string version;
  if (FILE* pipe = ::popen(command.c_str(), "r"))
  {
    char buffer[256];
    while (fgets(buffer, sizeof(buffer), pipe))
      version += buffer;
    ::pclose(pipe);
  }
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

class RecorderNode
{
public:
  RecorderNode(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), recorder_(nh)
  {
    events_ = nh.advertise<vrrw_msgs::Event>("/demos/events", 100);
    services_.push_back(nh.advertiseService("/demos/start", &RecorderNode::onStart, this));
    services_.push_back(nh.advertiseService("/demos/stop", &RecorderNode::onStop, this));
    services_.push_back(nh.advertiseService("/demos/annotate", &RecorderNode::onAnnotate, this));
    timer_ = nh.createWallTimer(ros::WallDuration(0.05), [this](const ros::WallTimerEvent&) { poll(); });
    const std::string file = pnh.param<std::string>("file", "");
    if (!file.empty())
    {
      const std::string error = start(file, pnh.param("robots", std::vector<std::string>{}));
      if (!error.empty())
        ROS_ERROR_STREAM("recorder: " << error);
    }
  }

  void shutdown()
  {
    if (!recorder_.recording())
      return;
    std::string file;
    uint64_t messages = 0;
    const std::string error = recorder_.stop(file, messages);
    if (error.empty())
      ROS_INFO_STREAM("recorder: " << file << ": " << messages << " messages");
    else
      ROS_ERROR_STREAM("recorder: " << error);
  }

private:
  std::string start(const std::string& file, std::vector<std::string> robots)
  {
    if (robots.empty())
      robots = sceneRobots(nh_);
    if (robots.empty())
      return "no robots: give them in the request, or bring a scene up first (/scene/robots is empty)";
    const std::string error = recorder_.start(file, robots, metadataYaml(nh_, robots, ros::Time::now()));
    if (error.empty())
      ROS_INFO_STREAM("recorder: recording " << robots.size() << " robot(s) to " << file);
    return error;
  }

  void poll()
  {
    recorder_.subscribeNewTopics();
    const std::string failure = recorder_.takeFailure();
    if (!failure.empty())
      ROS_ERROR_STREAM("recorder: " << failure);
  }

  bool onStart(vrrw_msgs::DemoStart::Request& request, vrrw_msgs::DemoStart::Response& response)
  {
    char* absolute = ::realpath(".", nullptr);  // a relative file is the recorder's working directory's
    std::string file = request.file;
    if (!file.empty() && file[0] != '/' && absolute)
      file = std::string(absolute) + "/" + file;
    std::free(absolute);
    response.message = start(file, request.robots);
    response.success = response.message.empty();
    if (response.success)
    {
      response.file = file;
      response.message = "recording to " + file;
    }
    return true;
  }

  bool onStop(vrrw_msgs::DemoStop::Request&, vrrw_msgs::DemoStop::Response& response)
  {
    response.message = recorder_.stop(response.file, response.messages);
    response.success = response.message.empty();
    if (response.success)
      response.message = std::to_string(response.messages) + " messages in " + response.file;
    else
      ROS_ERROR_STREAM("recorder: " << response.message);
    return true;
  }

  bool onAnnotate(vrrw_msgs::DemoAnnotate::Request& request, vrrw_msgs::DemoAnnotate::Response& response)
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

  ros::NodeHandle nh_;
  vrrw_demos::BagRecorder recorder_;
  ros::Publisher events_;
  std::vector<ros::ServiceServer> services_;
  ros::WallTimer timer_;
};
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "demo_recorder");
  ros::NodeHandle nh, pnh("~");
  RecorderNode node(nh, pnh);
  ros::spin();
  node.shutdown();
  return 0;
}
