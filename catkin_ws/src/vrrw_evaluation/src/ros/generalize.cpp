// PickPlaceDemo's generalization stage and its data files (pick_place_demo.cpp has the rest).
#include "pick_place_demo.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <vrrw_skills/trial_outcome.h>

namespace vrrw_evaluation
{
using vrrw_skills::judgeTrial;
using vrrw_skills::PlanarPose;
using vrrw_skills::planarPose;
using vrrw_skills::placeOnTable;
using vrrw_skills::sampleTrialPoses;
using vrrw_skills::TrialObservation;
using vrrw_skills::TrialOutcome;

namespace
{
/// The arm goal of each arm instruction for a drill standing at `object`, through IK seeded with the
/// demonstrated goal (same branch); near-pick must be collision-free, pick puts the fingers around it.
bool transferGoals(WorkspaceClient& client, const Demonstration& demo, const Eigen::Isometry3d& object,
                   const GraspGeometry& grasp, std::map<std::string, std::vector<double>>& goals, double& ik_ms,
                   std::string& error)
{
  auto demoGoal = [&](const std::string& name) { return positionsAt(demo.arm, demo.segment(name).end); };
  const auto near = client.ik(tcpAtNearPick(object, grasp), demoGoal("move_to_near_pick"), true, error, &ik_ms);
  if (!near)
    return error = "near-pick: " + error, false;
  const auto pick = client.ik(tcpAtGrasp(object, grasp), demoGoal("move_to_pick"), false, error, &ik_ms);
  if (!pick)
    return error = "pick: " + error, false;
  goals = { { "move_to_near_pick", *near },
            { "move_to_pick", *pick },
            { "back_to_near_pick", *near },
            { "move_to_final", demoGoal("move_to_final") } };
  return true;
}
}  // namespace

std::vector<double> PickPlaceDemo::placeGoal(const std::vector<double>& demonstrated, double& ik_ms)
{
  // The drill sits in this grasp a little differently than in the demonstration's: the goal that puts
  // it where the demonstration released it, through IK from how it is held now.
  const Eigen::Isometry3d held = client_.tcpPose().inverse() * client_.objectPose();
  std::string error;
  const auto goal = client_.ik(object_released_ * held.inverse(), demonstrated, false, error, &ik_ms);
  if (!goal || largestJointDifference(*goal, demonstrated) > 0.3)
    return demonstrated;
  return *goal;
}

void PickPlaceDemo::generalize(const Demonstration& demo, DemoReport& report)
{
  vrrw_dmp::DmpParameters parameters;
  parameters.basis_count = 30;
  parameters.scaling = vrrw_dmp::AmplitudeScaling::automatic;
  parameters.still_range = 0.02;  // rad: a wrist that merely drifts while the arm carries stays put
  const InstructionDmps dmps(demo, parameters);
  for (const std::string& name : dmps.instructions())
    report.dmp_fit_rmse_rad[name] = dmps.fitRmse(name);
  const Eigen::Isometry3d demo_end = object_end_;
  const auto poses = sampleTrialPoses(planarPose(object_start_), options_.spread, std::size_t(options_.trials),
                                      options_.seed);
  for (std::size_t k = 0; k < poses.size(); ++k)
  {
    TrialRecord trial;
    trial.trial = int(k);
    trial.x = poses[k].x;
    trial.y = poses[k].y;
    trial.yaw_deg = poses[k].yaw * 180.0 / M_PI;
    std::string error;
    std::map<std::string, std::vector<double>> goals;
    if (!resetObject(placeOnTable(object_start_, poses[k]), error))
      trial.reason = "reset: " + error;
    else if (!transferGoals(client_, demo, client_.objectPose(), options_.grasp, goals, trial.ik_ms, error))
      trial.reason = "skipped, " + error;
    else
    {
      trial.executed = true;
      TrialObservation seen;
      seen.object_start = client_.objectPose();
      std::vector<Instruction> instructions;
      for (const std::string& name : kInstructions)
        instructions.push_back([&, name](std::string& e) {
          if (name == "close_gripper")
            return client_.grip(demo.finger_closed, demo.grip_force, e);
          if (name == "open_gripper")
            return seen.gripper_open_at_end = client_.grip(demo.finger_open, 0.0, e);
          if (name == "move_to_final")
            goals[name] = placeGoal(goals[name], trial.ik_ms);
          return client_.execute(dmps.rollout(name, client_.armJoints(), goals.at(name), 0.01, client_.maxVelocities()), e);
        });
      Recording recording;
      std::vector<Segment> segments;
      if (!perform("trial_" + std::to_string(k), int(k) < options_.shown_trials, instructions, recording, segments,
                   error))
        seen.failed_instruction = error;
      seen.object_end = client_.objectPose();
      seen.arm_contacts = recording.arm_contacts;
      for (const TrackSample& s : recording.track)
        seen.max_lift = std::max(seen.max_lift, s.object.translation().z() - seen.object_start.translation().z());
      const TrialOutcome outcome = judgeTrial(seen, demo_end);
      trial.success = outcome.success;
      trial.reason = outcome.reason;
      trial.final_error_m = outcome.final_error_m;
      trial.final_angle_deg = outcome.final_angle_deg;
    }
    report.trials.push_back(trial);
    std::printf("demo: trial %zu/%zu at (%.3f, %.3f, %.1f deg): %s%s%s\n", k + 1, poses.size(), trial.x, trial.y,
                trial.yaw_deg, trial.success ? "success" : (trial.executed ? "failed" : "skipped"),
                trial.reason.empty() ? "" : ": ", trial.reason.c_str());
    std::fflush(stdout);
  }
}

void PickPlaceDemo::writeRecording(const std::string& row, const Recording& recording,
                                   const std::vector<Segment>& segments)
{
  const std::string base = options_.out + "/data/" + row;
  std::ofstream joints(base + "_joints.csv");
  joints << "t";
  for (const std::string& name : recording.arm.joint_names)
    joints << "," << name;
  joints << "\n";
  for (const auto& p : recording.arm.points)
  {
    joints << p.time;
    for (double q : p.positions)
      joints << "," << q;
    joints << "\n";
  }
  std::ofstream bounds(base + "_segments.csv");
  bounds << "name,start,end\n";
  for (const Segment& s : segments)
    bounds << s.name << "," << s.start << "," << s.end << "\n";
  std::ofstream track(base + "_track.csv");
  track << "t,tcp_x,tcp_y,tcp_z,object_x,object_y,object_z,object_yaw\n";
  for (const TrackSample& s : recording.track)
  {
    const PlanarPose planar = planarPose(s.object);
    track << s.time << "," << s.tcp.x() << "," << s.tcp.y() << "," << s.tcp.z() << "," << planar.x << "," << planar.y
          << "," << s.object.translation().z() << "," << planar.yaw << "\n";
  }
}
}  // namespace vrrw_evaluation
