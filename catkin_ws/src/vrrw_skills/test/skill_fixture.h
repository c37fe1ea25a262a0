#pragma once
// A skill built in code (no bag, no URDF), a toy arm whose joints are its TCP pose, and a demonstration built in
// code as the learner reads a bag's, for the core's tests.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <vrrw_demos/demonstration.h>
#include <vrrw_dmp/quaternion_maps.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/skill.h>
#include <vrrw_skills/skill_learning.h>
#include <vrrw_demos/segmentation.h>
#include <vrrw_skills/skill_plan.h>

#include "xyz_robot.h"  // vrrw_demos/test/

namespace vrrw_skills_test
{
using vrrw_skills::CartesianPose;

inline CartesianPose pose(double x, double y, double z, double yaw = 0.0)
{
  // the tool pointing down, turned by yaw about the world's z
  return { Eigen::Vector3d(x, y, z), Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())) *
                                         Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0) };  // down(), turned
}

/// The tool pointing down: the toy arm's orientation joints count from it.
inline Eigen::Quaterniond down()
{
  return Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0);
}

/// A toy arm's joints: the TCP's position and its rotation vector from pointing down, so IK and FK are exact,
/// cheap and continuous about the poses a pick uses.
inline std::vector<double> jointsOf(const CartesianPose& tcp)
{
  const Eigen::Vector3d r = 2.0 * vrrw_dmp::quaternionLog(tcp.orientation * down().conjugate());
  return { tcp.position.x(), tcp.position.y(), tcp.position.z(), r.x(), r.y(), r.z() };
}

inline CartesianPose poseOf(const std::vector<double>& q)
{
  return { Eigen::Vector3d(q[0], q[1], q[2]),
           vrrw_dmp::quaternionExp(0.5 * Eigen::Vector3d(q[3], q[4], q[5])) * down() };
}

/// A minimum-jerk move of the toy arm from \a a to \a b over \a seconds, sampled at 100 Hz.
inline vrrw_trajectory::JointTrajectory move(const CartesianPose& a, const CartesianPose& b, double seconds)
{
  vrrw_trajectory::JointTrajectory out;
  out.joint_names = { "x", "y", "z", "rx", "ry", "rz" };
  const auto qa = jointsOf(a), qb = jointsOf(b);
  for (int k = 0; k <= int(seconds * 100); ++k)
  {
    const double u = k / (seconds * 100), s = u * u * u * (10 - 15 * u + 6 * u * u);
    std::vector<double> q(6);
    for (int j = 0; j < 6; ++j)
      q[j] = qa[j] + s * (qb[j] - qa[j]);
    out.points.push_back({ k * 0.01, q, {}, {} });
  }
  return out;
}

inline vrrw_skills::SkillInstruction armInstruction(const std::string& name, const CartesianPose& from,
                                                    const CartesianPose& to, vrrw_skills::Frame frame,
                                                    const CartesianPose& frame_pose, double seconds)
{
  vrrw_skills::SkillInstruction out;
  out.name = name;
  out.duration = seconds;
  out.start = { vrrw_skills::Frame::world, from };
  out.end = { frame, frame == vrrw_skills::Frame::world ? to : vrrw_skills::relativeTo(frame_pose, to) };
  out.joints_start = jointsOf(from);
  out.joints_end = jointsOf(to);
  const auto motion = move(from, to, seconds);
  std::vector<vrrw_dmp::CartesianSample> path;
  for (const auto& point : motion.points)
    path.push_back({ point.time, poseOf(point.positions), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() });
  vrrw_dmp::DmpProvenance provenance;
  provenance.source = "test " + name;
  provenance.created = "2026-01-01T00:00:00Z";
  out.joint_dmp = vrrw_dmp::Dmp::learn(motion, vrrw_skills::skillDmpParameters(), provenance);
  out.cartesian_dmp = vrrw_dmp::CartesianDmp::learn(path, vrrw_skills::skillDmpParameters(), provenance);
  out.joint_fit_rmse = 1e-4;
  out.cartesian_fit_rmse = 2e-4;
  out.cartesian_fit_rmse_deg = 0.01;
  return out;
}

inline vrrw_skills::SkillInstruction gripperInstruction(const std::string& name, double position, double effort)
{
  vrrw_skills::SkillInstruction out;
  out.name = name;
  out.gripper = true;
  out.duration = 0.8;
  out.gripper_position = position;
  out.gripper_reached = position * 0.6;
  out.gripper_effort = effort;
  return out;
}

/// A pick-and-place of an object at (0.4, 0.1) taken from 20 cm above its base and put down 30 cm to the side.
inline vrrw_skills::Skill pickAndPlace()
{
  using vrrw_skills::Frame;
  vrrw_skills::Skill skill;
  skill.robot = "toy";
  skill.arm_joints = { "x", "y", "z", "rx", "ry", "rz" };
  skill.tcp_link = "toy_tcp";
  skill.gripper_joint = "toy_finger_joint";
  skill.object = "box";
  skill.object_start = { Eigen::Vector3d(0.4, 0.1, 0.75), Eigen::Quaterniond::Identity() };
  skill.object_end = { Eigen::Vector3d(0.4, -0.2, 0.75), Eigen::Quaterniond::Identity() };
  skill.object_in_hand = vrrw_skills::relativeTo(pose(0.4, 0.1, 0.95), skill.object_start);
  const CartesianPose home = pose(0.2, 0.3, 1.2), approach = pose(0.4, 0.1, 1.07), grasp = pose(0.4, 0.1, 0.95),
                      place = pose(0.4, -0.2, 0.95);
  skill.joints_home = jointsOf(home);
  skill.instructions = { armInstruction("near_pick", home, approach, Frame::object, skill.object_start, 2.0),
                         armInstruction("pick", approach, grasp, Frame::object, skill.object_start, 1.2),
                         gripperInstruction("close_gripper", 0.8, 70.0),
                         armInstruction("back_to_near_pick", grasp, approach, Frame::object, skill.object_start, 1.2),
                         armInstruction("final", approach, place, Frame::world, skill.object_start, 2.5),
                         gripperInstruction("open_gripper", 0.0, 0.0) };
  skill.sources = { { "/tmp/demo.bag", "toy_cell", "v1", 12.5, { { "near_pick", 0.5, 2.5 }, { "pick", 3.0, 4.2 } } } };
  skill.created = "2026-01-01T00:00:00Z";
  skill.tool = "vrrw_skills test";
  return skill;
}

/// The toy arm: IK is exact inside a reach of \a reach m from the origin, refused beyond; checkPath() asks \a touches per state.
class ToyArm : public vrrw_skills::ArmKinematics
{
public:
  double reach = 2.0;
  std::function<vrrw_skills::ContactPair(const std::vector<double>&)> touches = [](const std::vector<double>&) {
    return vrrw_skills::ContactPair{};
  };
  int ik_calls = 0, checks = 0, path_checks = 0;

  vrrw_skills::IkAnswer ik(const CartesianPose& tcp, const std::vector<double>&, bool) override
  {
    ++ik_calls;
    if (tcp.position.norm() > reach)
      return { std::nullopt, "out of reach (" + std::to_string(tcp.position.norm()) + " m)" };
    return { jointsOf(tcp), "" };
  }
  std::vector<vrrw_skills::ContactPair> checkPath(const std::vector<std::vector<double>>& path) override
  {
    ++path_checks;
    std::vector<vrrw_skills::ContactPair> pairs;
    for (const auto& joints : path)
    {
      ++checks;
      pairs.push_back(touches(joints));
    }
    return pairs;
  }
  CartesianPose tcp(const std::vector<double>& joints) override { return poseOf(joints); }
};

/// A pick-and-place by the xyz robot at 100 Hz with pauses: a box at (0.4, 0.1, 0.8) taken 15 cm above its
/// centre (the TCP at 0.95), lifted, carried 30 cm in y and set down; the box follows the TCP while held.
inline vrrw_demos::Demonstration xyzPickPlace(const std::string& source = "xyz.bag")
{
  struct Move
  {
    double start, duration;
    Eigen::Vector3d to;
  };
  const Eigen::Vector3d home(0.2, 0.3, 1.2);
  const std::vector<Move> moves{ { 0.5, 1.5, { 0.4, 0.1, 1.07 } },  { 3.0, 1.0, { 0.4, 0.1, 0.95 } },
                                 { 5.5, 1.0, { 0.4, 0.1, 1.07 } },  { 8.0, 2.0, { 0.4, -0.2, 1.07 } },
                                 { 10.5, 1.0, { 0.4, -0.2, 0.95 } } };
  const double close = 4.3, open = 12.0, end = 13.5;
  vrrw_demos::Demonstration demo;
  demo.source = source;
  demo.metadata.scene = "xyz_cell";
  vrrw_demos::RobotTrack& track = vrrw_demos_test::addXyzRobot(demo, close, open);
  auto jerk = [](double u) { u = std::clamp(u, 0.0, 1.0); return u * u * u * (10 - 15 * u + 6 * u * u); };
  for (int k = 0; k * 0.01 <= end; ++k)
  {
    const double t = k * 0.01;
    Eigen::Vector3d q = home, from = home;
    for (const Move& m : moves)
    {
      q = from + jerk((t - m.start) / m.duration) * (m.to - from);
      if (t < m.start + m.duration)
        break;
      from = m.to;
    }
    vrrw_demos::RobotState state;
    state.time = t;
    state.positions = { q.x(), q.y(), q.z() };
    state.velocities = { 0.0, 0.0, 0.0 };
    state.gripper = 0.5 * jerk((t - close) / 0.4) - 0.5 * jerk((t - open) / 0.4);  // stalls at 0.5 on the box
    track.states.push_back(state);
  }
  auto& box = demo.objects["box"];
  for (int k = 0; k * 0.05 <= end; ++k)
  {
    const double t = k * 0.05;
    const vrrw_demos::RobotState held = vrrw_demos::stateAt(track, std::clamp(t, close + 0.4, open));
    vrrw_demos::TimedPose pose;
    pose.time = t;
    pose.pose.position[0] = held.positions[0];
    pose.pose.position[1] = held.positions[1];
    pose.pose.position[2] = held.positions[2] - 0.15;
    box.push_back(pose);
  }
  demo.objects["table"].push_back({});
  return demo;
}
}  // namespace vrrw_skills_test
