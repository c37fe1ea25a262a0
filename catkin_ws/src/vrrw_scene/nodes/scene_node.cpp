// Publishes a scene's objects (tf + markers) and, until a controller or physics takes over,
// holds every robot joint at its initial value on /joint_states and /<robot>/joint_states.
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

#include "vrrw_scene/scene_loader.h"

namespace
{
geometry_msgs::Pose toPose(const Eigen::Isometry3d& pose)
{
  geometry_msgs::Pose out;
  const Eigen::Quaterniond q(pose.linear());
  out.position.x = pose.translation().x();
  out.position.y = pose.translation().y();
  out.position.z = pose.translation().z();
  out.orientation.w = q.w();
  out.orientation.x = q.x();
  out.orientation.y = q.y();
  out.orientation.z = q.z();
  return out;
}

visualization_msgs::Marker shapeMarker(const vrrw_scene::Object& object, const vrrw_scene::Shape& shape, int id)
{
  using vrrw_scene::Shape;
  visualization_msgs::Marker marker;
  marker.header.frame_id = object.name;
  marker.ns = object.name;
  marker.id = id;
  marker.pose = toPose(shape.origin);
  marker.color.r = object.color[0];
  marker.color.g = object.color[1];
  marker.color.b = object.color[2];
  marker.color.a = object.color[3];
  switch (shape.type)
  {
    case Shape::Type::Box:
      marker.type = visualization_msgs::Marker::CUBE;
      marker.scale.x = shape.box_size.x();
      marker.scale.y = shape.box_size.y();
      marker.scale.z = shape.box_size.z();
      break;
    case Shape::Type::Cylinder:
      marker.type = visualization_msgs::Marker::CYLINDER;
      marker.scale.x = marker.scale.y = 2 * shape.radius;
      marker.scale.z = shape.length;
      break;
    case Shape::Type::Sphere:
      marker.type = visualization_msgs::Marker::SPHERE;
      marker.scale.x = marker.scale.y = marker.scale.z = 2 * shape.radius;
      break;
    case Shape::Type::Mesh:
      marker.type = visualization_msgs::Marker::MESH_RESOURCE;
      marker.mesh_resource = "file://" + shape.mesh_path;
      marker.scale.x = shape.mesh_scale.x();
      marker.scale.y = shape.mesh_scale.y();
      marker.scale.z = shape.mesh_scale.z();
      break;
  }
  return marker;
}
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "scene_node");
  ros::NodeHandle nh, pnh("~");
  const std::string scene_name = pnh.param<std::string>("scene", "");
  const bool hold_joints = pnh.param("hold_joints", true);
  const bool publish_objects = pnh.param("publish_object_poses", true);
  const double rate_hz = pnh.param("rate", 30.0);
  vrrw_scene::Scene scene;
  try
  {
    scene = vrrw_scene::loadScene(scene_name);
  }
  catch (const vrrw_scene::SceneError& e)  // nothing to publish without the scene: the node does not start
  {
    ROS_FATAL("scene_node: ~scene '%s': %s", scene_name.c_str(), e.what());
    return 2;
  }
  catch (const std::exception& e)
  {
    ROS_FATAL("scene_node: ~scene '%s': %s", scene_name.c_str(), e.what());
    return 1;
  }
  ROS_INFO("scene %s: %zu robots, %zu objects, loaded in %.3f s (%s)", scene.name.c_str(), scene.robots.size(),
           scene.objects.size(), scene.load_seconds, scene.from_cache ? "cache" : "xacro");

  for (const auto& robot : scene.robots)
  {
    const std::string key = "scene/robots/" + robot.name + "/";
    nh.setParam(key + "model", robot.model);
    nh.setParam(key + "gripper", robot.gripper);
    nh.setParam(key + "base_link", robot.base_link);
    nh.setParam(key + "arm_base_link", robot.arm_base_link);
    nh.setParam(key + "tool_link", robot.tool_link);
    nh.setParam(key + "tcp_link", robot.tcp_link);
    nh.setParam(key + "arm_joints", robot.arm_joints);
    nh.setParam(key + "gripper_joints", robot.gripper_joints);
    nh.setParam(key + "config_file", robot.config_file);
  }
  nh.setParam("scene/name", scene.name);
  nh.setParam("scene/file", scene.source_file);

  tf2_ros::StaticTransformBroadcaster static_tf;
  visualization_msgs::MarkerArray markers;
  std::vector<geometry_msgs::TransformStamped> object_frames;
  for (const auto& object : scene.objects)
  {
    int id = 0;
    for (const auto& shape : object.visual)
      markers.markers.push_back(shapeMarker(object, shape, id++));
    geometry_msgs::TransformStamped frame;
    frame.header.frame_id = "world";
    frame.child_frame_id = object.name;
    const auto pose = toPose(object.pose);
    frame.transform.translation.x = pose.position.x;
    frame.transform.translation.y = pose.position.y;
    frame.transform.translation.z = pose.position.z;
    frame.transform.rotation = pose.orientation;
    object_frames.push_back(frame);
  }
  if (publish_objects)
    static_tf.sendTransform(object_frames);
  auto marker_pub = nh.advertise<visualization_msgs::MarkerArray>("scene/objects", 1, true);
  marker_pub.publish(markers);

  if (!hold_joints)
  {
    ros::spin();
    return 0;
  }
  // One /joint_states message per cycle holding every robot's joints: robot_state_publisher subscribes
  // with a queue of one, so of several messages sent back to back it may keep only the last, and a
  // robot whose message is always overwritten never gets its links into tf.
  auto all_pub = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
  sensor_msgs::JointState all;
  std::vector<std::pair<ros::Publisher, sensor_msgs::JointState>> robots;
  for (const auto& robot : scene.robots)
  {
    sensor_msgs::JointState state;
    for (const auto& [joint, value] : robot.initial_positions)
    {
      state.name.push_back(joint);
      state.position.push_back(value);
    }
    state.velocity.assign(state.name.size(), 0.0);
    state.effort.assign(state.name.size(), 0.0);
    all.name.insert(all.name.end(), state.name.begin(), state.name.end());
    all.position.insert(all.position.end(), state.position.begin(), state.position.end());
    robots.emplace_back(nh.advertise<sensor_msgs::JointState>(robot.name + "/joint_states", 10), state);
  }
  all.velocity.assign(all.name.size(), 0.0);
  all.effort.assign(all.name.size(), 0.0);
  ros::Rate rate(rate_hz);
  while (ros::ok())
  {
    all.header.stamp = ros::Time::now();
    for (auto& [pub, state] : robots)
    {
      state.header.stamp = all.header.stamp;
      pub.publish(state);
    }
    all_pub.publish(all);
    ros::spinOnce();
    rate.sleep();
  }
  return 0;
}
