#include "pick_place_demo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vrrw_common/run_program.h>
#include <vrrw_skills/trial_outcome.h>

#include <vrrw_demos/ros/demo_bag.h>
#include <vrrw_evaluation/annotations.h>
#include <vrrw_evaluation/joint_paths.h>

namespace vrrw_evaluation
{
namespace
{
/// Simulated s the operator rests between two instructions of the teach. Paced, the script's own calls took about
/// this long; in lockstep they take no simulated time, and the skill learner's keyframe rule finds an instruction's
/// end where the arm rests (without the rest it ran the lift on into the carry).
constexpr double kOperatorPause = 0.4;
}  // namespace

void progress(const std::string& line)
{
  std::printf("demo: %s\n", line.c_str());
  std::fflush(stdout);
}

PickPlaceDemo::PickPlaceDemo(ros::NodeHandle& node, WorkspaceClient& client, GhostOperator& ghost, HandOperator& hand,
                             const Cell& cell, DemoOptions options)
  : node_(node), client_(client), ghost_(ghost), hand_(hand), cell_(cell), options_(std::move(options))
{
  std::filesystem::create_directories(options_.out + "/data");
  std::filesystem::create_directories(options_.out + "/frames");
}

bool PickPlaceDemo::moveLinear(const std::vector<std::pair<Eigen::Isometry3d, double>>& legs, std::string& error)
{
  constexpr double kSample = 0.04;
  vrrw_trajectory::JointTrajectory trajectory;
  trajectory.joint_names = client_.robot().arm_joints;
  std::vector<double> q = client_.armJoints();
  Eigen::Isometry3d from = client_.tcpPose();
  trajectory.points.push_back({ 0.0, q, {}, {} });
  double time = 0.0;
  for (const auto& [to, seconds] : legs)
  {
    const int samples = std::max(2, int(std::lround(seconds / kSample)));
    for (int k = 1; k <= samples; ++k)
    {
      const auto solution = client_.ik(interpolatePose(from, to, minimumJerk(double(k) / samples)), q, false, error);
      if (!solution)
        return error = "TCP line: " + error, false;
      q = *solution;
      trajectory.points.push_back({ time + seconds * k / samples, q, {}, {} });
    }
    time += seconds;
    from = to;
  }
  addVelocities(trajectory);
  return client_.execute(trajectory, error);
}

bool PickPlaceDemo::goHome(std::string& error)
{
  if (home_.empty() || largestJointDifference(client_.armJoints(), home_) < 1e-3)
    return true;
  Eigen::Isometry3d up = client_.tcpPose();
  up.translation().z() += 0.10;
  if (!moveLinear({ { up, 0.8 } }, error))
    return false;
  std::string why;
  auto planned = client_.plan(home_, why);
  if (!planned)
  {
    // A direct joint move is safe from up there; say that the planner failed.
    progress("plan home failed (" + why + "); moving home in joint space");
    vrrw_trajectory::JointTrajectory direct;
    direct.joint_names = client_.robot().arm_joints;
    const std::vector<double> q = client_.armJoints();
    for (int k = 0; k <= 20; ++k)
    {
      std::vector<double> p(q.size());
      for (std::size_t j = 0; j < q.size(); ++j)
        p[j] = q[j] + minimumJerk(k / 20.0) * (home_[j] - q[j]);
      direct.points.push_back({ 2.0 * k / 20.0, p, {}, {} });
    }
    addVelocities(direct);
    planned = direct;
  }
  return client_.execute(*planned, error);
}

bool PickPlaceDemo::resetObject(const Eigen::Isometry3d& pose, std::string& error)
{
  // Open first: a trial that failed holding the drill must not carry it home nor close on it again.
  if (!client_.grip(options_.grasp.finger_open, 0.0, error) || !goHome(error) || !client_.placeObject(pose, error))
    return false;
  client_.settle(0.3);  // the drill settles on the table
  return true;
}

void PickPlaceDemo::capture(const std::string& row, std::size_t boundary, bool frames)
{
  if (!frames || options_.capture_command.empty())
    return;
  ros::WallDuration(0.15).sleep();  // rviz (10 Hz) draws the state published where the simulation waits
  // the command's words as arguments, the file as one of them: no shell ever reads the --out path
  const std::string file = options_.out + "/frames/" + row + "_" + std::to_string(boundary) + ".png";
  std::istringstream words(options_.capture_command);
  std::vector<std::string> argv;
  for (std::string word; words >> word;)
    argv.push_back(word == "{file}" ? file : word);
  if (vrrw_common::runProgram(argv) != 0)
    progress("frame capture failed: " + options_.capture_command + " (file " + file + ")");
}

bool PickPlaceDemo::perform(const std::string& row, bool frames, const std::vector<Instruction>& instructions,
                            Recording& recording, std::vector<Segment>& segments, std::string& error)
{
  try
  {
    client_.startRecording(row == "demonstration" ? options_.out + "/demonstration.bag" : "");
  }
  catch (const std::runtime_error& e)  // the recorder did not take the bag
  {
    return error = e.what(), false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < instructions.size() && ok; ++i)
  {
    Segment segment;
    segment.name = kInstructions[i];
    segment.start = client_.recordingTime();
    client_.annotate("instruction_start", kInstructions[i]);
    ok = instructions[i](error);
    segment.end = client_.recordingTime();
    client_.annotate(ok ? "instruction_end" : "instruction_failed", kInstructions[i]);
    segments.push_back(segment);
    if (!ok)
      error = kInstructions[i] + ": " + error;
    else
      capture(row, i + 1, frames);
    if (ok && row == "demonstration" && i + 1 < instructions.size())
      client_.settle(kOperatorPause);
  }
  client_.settle(0.5);  // the released drill comes to rest, still recorded
  recording = client_.stopRecording();
  writeRecording(row, recording, segments);
  return ok;
}

bool PickPlaceDemo::teach(DemoReport& report, std::string& error)
{
  home_ = client_.armJoints();
  object_start_ = client_.objectPose();
  const GraspGeometry& grasp = options_.grasp;
  Eigen::Isometry3d object_final = object_start_;
  object_final.translation() += Eigen::Vector3d(options_.final_offset.x(), options_.final_offset.y(),
                                                grasp.release_height);
  const Eigen::Isometry3d near_pick = tcpAtNearPick(object_start_, grasp);
  const Eigen::Isometry3d pick = tcpAtGrasp(object_start_, grasp);
  const Eigen::Isometry3d place = tcpAtGrasp(object_final, grasp);
  Eigen::Isometry3d above_place = place;
  above_place.translation().z() = near_pick.translation().z();
  double plan_ms = 0.0;
  const std::string gripper = "/" + client_.robot().name + "/gripper_controller/gripper_cmd";
  report.teach_interfaces.clear();
  auto used = [&](const std::vector<std::string>& interfaces) {
    report.teach_interfaces.push_back({ kInstructions[report.teach_interfaces.size()], interfaces });
  };
  auto drive = [&](const std::vector<Eigen::Isometry3d>& waypoints, const Eigen::Isometry3d& goal, std::string& e,
                   const DriveOptions& how = {}) {
    const bool ok = ghost_.drive(waypoints, goal, e, &plan_ms, how);
    return used(ghost_.takeUsed()), ok;
  };
  auto grip = [&](double position, double force, std::string& e) {
    return used({ gripper }), client_.grip(position, force, e);
  };
  // The arm moves by ghost-drive with waypoints, and by free-drive down to the grasp (the hand on the wrist
  // pulls the compliant arm along a minimum-jerk line). Stops at waypoints on a line keep a motion straight and
  // slow enough to replay. The approach goes via a waypoint halfway from the TCP at home to near-pick: one
  // off that line (e.g. above near-pick) makes joints go and come back, which the DMPs' amplitude scaling
  // magnifies for new goals (the arm then swept through the drill). The carry is minimum-jerk at a quarter of
  // the acceleration limits (time-optimal plans step the acceleration and swing the drill in the two-finger
  // grip) and the place presses the drill onto the table (its support surface), so it stands flat before the
  // fingers open.
  const DriveOptions carry{ 1.0, options_.carry_acceleration_scaling, "minimum_jerk", "" };
  DriveOptions place_on_table = carry;
  place_on_table.support_surface = options_.table;
  const Eigen::Isometry3d halfway = interpolatePose(client_.tcpPose(), near_pick, 0.5);
  const std::vector<Instruction> script = {
    [&](std::string& e) { return drive({ halfway }, near_pick, e); },
    [&](std::string& e) {
      const bool ok = hand_.freeDrive(client_.tcpPose(), pick, client_.flangePose().translation(),
                                      options_.descent_seconds, 0.3, e);
      return used(hand_.takeUsed()), ok;
    },
    [&](std::string& e) { return grip(grasp.finger_closed, grasp.grip_force, e); },
    [&](std::string& e) { return drive({}, near_pick, e, carry); },
    [&](std::string& e) { return drive({ above_place }, place, e, place_on_table); },
    [&](std::string& e) { return grip(grasp.finger_open, 0.0, e); },
  };
  Recording recording;
  std::vector<Segment> scripted;
  if (!perform("demonstration", true, script, recording, scripted, error))
    return false;
  object_end_ = client_.objectPose();
  report.teach_source = "scripted operator: ghost-drive with waypoints to near-pick, free-drive (a hand on the wrist) "
                        "down to the grasp, GripperCommand, ghost-drive back up and to the place (the " +
                        options_.table + " as its support surface)";
  report.teach_seconds = recording.seconds;
  report.teach_start_stamp = recording.start_stamp;
  report.segments = scripted;
  report.plan_ms = plan_ms;
  report.message_counts["/" + client_.robot().name + "/joint_states"] = recording.joint_state_messages;
  report.message_counts["/physics/contacts"] = recording.contact_messages;
  report.message_counts["/demos/events"] = recording.event_messages;
  report.bag_messages = recording.bag_messages;
  report.bag_file = recording.bag_file;
  report.teach_source += "; bag by vrrw_demos recorder_node";
  if (!recording.arm_contacts.empty())
    progress("warning: the demonstration touched " + *recording.arm_contacts.begin());
  return true;
}

bool PickPlaceDemo::segment(DemoReport& report, std::string& error)
{
  if (report.bag_file.empty())
    return error = "no bag was recorded", false;
  try
  {
    shown_ = vrrw_demos::readDemonstration(report.bag_file, { client_.robot().name });
    instructions_ = annotatedInstructions(shown_);
  }
  catch (const std::exception& e)
  {
    return error = e.what(), false;
  }
  std::string names;
  for (const Segment& s : instructions_)
    names += (names.empty() ? "" : ", ") + s.name;
  if (instructions_.size() != kInstructions.size() ||
      !std::equal(kInstructions.begin(), kInstructions.end(), instructions_.begin(),
                  [](const std::string& k, const Segment& s) { return k == s.name; }))
    return error = report.bag_file + ": /demos/events: instructions " + (names.empty() ? "none" : names) +
                   " (expected the six of the paper in order)",
           false;
  // the bag's times count from the recorder's start, the script's from the runner's: the same instant
  const double offset = shown_.start_stamp - report.teach_start_stamp;
  double shift = 0.0;
  for (std::size_t i = 0; i < instructions_.size(); ++i)
    shift = std::max({ shift, std::abs(instructions_[i].start + offset - report.segments[i].start),
                       std::abs(instructions_[i].end + offset - report.segments[i].end) });
  char within[64];
  std::snprintf(within, sizeof within, "%.1f ms", shift * 1e3);
  progress("segments from " + report.bag_file + " (/demos/events), within " + within + " of the script's clock");
  report.segments = instructions_;
  for (Segment& s : report.segments)
    s.start += offset, s.end += offset;
  return true;
}

bool PickPlaceDemo::replay(DemoReport& report, std::string& error)
{
  if (!resetObject(object_start_, error))
    return false;
  const vrrw_demos::RobotTrack& track = shown_.robots.front();
  std::vector<Instruction> instructions;
  for (const Segment& segment : instructions_)
    instructions.push_back([&, segment](std::string& e) {
      if (segment.gripper)
      {
        // the goal the operator sent in this instruction: its position and effort
        vrrw_demos::GripperGoal goal{ segment.start, segment.name == "close_gripper" ? options_.grasp.finger_closed
                                                                                    : options_.grasp.finger_open, 0.0 };
        for (const vrrw_demos::GripperGoal& sent : track.gripper_goals)
          if (sent.time >= segment.start - 0.05 && sent.time <= segment.end)
            goal = sent;
        return client_.grip(goal.position, goal.max_effort, e);
      }
      return client_.execute(instructionGoal(track, segment.start, segment.end), e);
    });
  Recording recording;
  std::vector<Segment> segments;
  if (!perform("replay", true, instructions, recording, segments, error))
    return false;
  const Eigen::Isometry3d end = client_.objectPose();
  report.replay_object_position_error_m = (end.translation() - object_end_.translation()).norm();
  report.replay_object_angle_error_deg =
      Eigen::AngleAxisd(end.rotation() * object_end_.rotation().transpose()).angle() * 180.0 / M_PI;
  const vrrw_demos::RobotTrack replayed = asTrack(recording.arm, track.robot);
  double sum = 0.0, duration = 0.0;
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    if (isGripperInstruction(segments[i].name))
      continue;
    const auto reference = instructionGoal(track, instructions_[i].start, instructions_[i].end);
    const double rms = jointRms(reference, instructionGoal(replayed, segments[i].start, segments[i].end));
    report.replay_segment_rms_rad[segments[i].name] = rms;
    sum += rms * rms * reference.duration();
    duration += reference.duration();
  }
  report.replay_joint_rms_rad = std::sqrt(sum / std::max(duration, 1e-9));
  return true;
}
}  // namespace vrrw_evaluation
