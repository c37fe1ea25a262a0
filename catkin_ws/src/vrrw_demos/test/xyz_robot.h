#pragma once
// A robot whose joints are its TCP's x, y and z (a URDF of three prismatic joints), for demonstrations built in
// code that segmentation and the skill learner read as they read a bag's. Used by vrrw_demos' and vrrw_skills'
// tests (vrrw_skills adds this folder to its tests' include path).
#include <vrrw_demos/demonstration.h>

namespace vrrw_demos_test
{
inline const char* kXyzRobot = R"(<robot name="xyz">
  <link name="world"/><link name="bot_x"/><link name="bot_y"/><link name="bot_tcp"/>
  <joint name="bot_x_joint" type="prismatic"><parent link="world"/><child link="bot_x"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <joint name="bot_y_joint" type="prismatic"><parent link="bot_x"/><child link="bot_y"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <joint name="bot_z_joint" type="prismatic"><parent link="bot_y"/><child link="bot_tcp"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
</robot>)";

/// \brief The xyz robot "bot" in \a demo: its URDF and TCP in the metadata, and its track (no states yet):
/// joints bot_x/y/z_joint, gripper bot_finger_joint, a close goal (0.8, 40 N) at \a close s and an open at \a open.
inline vrrw_demos::RobotTrack& addXyzRobot(vrrw_demos::Demonstration& demo, double close, double open)
{
  demo.metadata.robot_description = kXyzRobot;
  demo.metadata.robots["bot"].tcp_link = "bot_tcp";
  vrrw_demos::RobotTrack& track = demo.robots.emplace_back();
  track.robot = "bot";
  track.joint_names = { "bot_x_joint", "bot_y_joint", "bot_z_joint" };
  track.gripper_joint = "bot_finger_joint";
  track.gripper_goals = { { close, 0.8, 40.0 }, { open, 0.0, 0.0 } };
  return track;
}
}  // namespace vrrw_demos_test
