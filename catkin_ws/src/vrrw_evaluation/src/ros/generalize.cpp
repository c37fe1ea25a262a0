// PickPlaceDemo's generalization stage and its data files (pick_place_demo.cpp has the rest): the skill learned
// from the demonstration's bag (`./vrrw skill learn`'s code) and tried on new drill poses (`skill evaluate`'s).
#include "pick_place_demo.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <vrrw_common/ros/persistent_service.h>
#include <vrrw_skills/evaluation.h>
#include <vrrw_skills/poses.h>
#include <vrrw_skills/ros/skill_trials.h>
#include <vrrw_skills/skill_learning.h>
#include <vrrw_skills/skill_yaml.h>

namespace vrrw_evaluation
{
vrrw_skills::Skill PickPlaceDemo::learnSkill(DemoReport& report)
{
  vrrw_skills::LearnOptions learn;
  learn.object = cell_.object;
  learn.robot = client_.robot().name;
  const auto start = std::chrono::steady_clock::now();
  const vrrw_skills::Skill skill = vrrw_skills::learnSkill({ shown_ }, learn);
  report.skill.learn_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string file = options_.out + "/skill.yaml";
  std::filesystem::remove(file);  // a report folder of an earlier run
  vrrw_skills::saveSkill(skill, file);
  report.skill.file = "skill.yaml";
  // the learner knows only the bag; the script knows what it meant: the two grasps in the drill's frame
  const Eigen::Isometry3d taught = object_start_.inverse() * tcpAtGrasp(object_start_, options_.grasp);
  const Eigen::Isometry3d learned = vrrw_skills::toIsometry(skill.grasp().pose);
  for (int i = 0; i < 3; ++i)
  {
    report.skill.grasp_taught[i] = taught.translation()[i];
    report.skill.grasp_learned[i] = learned.translation()[i];
  }
  report.skill.grasp_error_mm = 1000.0 * (learned.translation() - taught.translation()).norm();
  report.skill.grasp_error_deg =
      Eigen::AngleAxisd(learned.rotation() * taught.rotation().transpose()).angle() * 180.0 / M_PI;
  for (const vrrw_skills::SkillInstruction* instruction : skill.armInstructions())
  {
    report.dmp_fit_rmse_rad[instruction->name] = instruction->joint_fit_rmse;
    report.skill.cartesian_fit_rmse_m[instruction->name] = instruction->cartesian_fit_rmse;
    report.skill.cartesian_fit_rmse_deg[instruction->name] = instruction->cartesian_fit_rmse_deg;
  }
  char line[160];
  std::snprintf(line, sizeof line, "skill learned from %s in %.2f s: grasp %.2f mm / %.2f deg from the script's",
                report.bag_file.c_str(), report.skill.learn_seconds, report.skill.grasp_error_mm,
                report.skill.grasp_error_deg);
  progress(line);
  return skill;
}

void PickPlaceDemo::generalize(DemoReport& report)
{
  vrrw_skills::Skill skill;
  try
  {
    skill = learnSkill(report);
  }
  catch (const std::exception& e)
  {
    progress("skill learn failed: " + std::string(e.what()));
    return;
  }
  vrrw_common::PersistentServices services;
  vrrw_skills::WorkspaceArm arm(node_, client_.robot().name, services);
  arm.holdSimulation(client_.simulation());  // the trials step the simulation the runner holds
  arm.waitUntilReady(10.0);
  vrrw_skills::ArmServices kinematics(services, arm.robot(), arm.armJoints());
  vrrw_skills::SkillTrials trials(node_, skill, arm, kinematics, services, cell_.object, cell_.obstacles);
  vrrw_skills::EvaluationOptions evaluation;
  evaluation.trials = std::size_t(options_.trials);
  evaluation.seed = options_.seed;
  evaluation.spread = options_.spread;
  const auto poses = vrrw_skills::evaluationPoses(skill, evaluation);
  for (std::size_t k = 0; k < poses.size(); ++k)
  {
    const std::string row = "trial_" + std::to_string(k + 1);  // trials count from 1, as the progress lines
    const bool frames = int(k) < options_.shown_trials;
    client_.startRecording();
    std::vector<Segment> segments;
    double last = client_.recordingTime();
    auto done = [&](const std::string& name) {
      Segment segment;
      segment.name = name;
      segment.start = last;
      segment.end = last = client_.recordingTime();
      segments.push_back(segment);
      capture(row, segments.size(), frames);
    };
    const std::string label = "trial " + std::to_string(k + 1) + "/" + std::to_string(poses.size());
    const vrrw_skills::TrialResult result =
        trials.trial(int(k + 1), poses[k], [&](const std::string& line) { progress(label + ": " + line); }, done);
    writeRecording(row, client_.stopRecording(), segments);
    TrialRecord trial;
    trial.trial = result.trial;
    trial.x = result.x;
    trial.y = result.y;
    trial.yaw_deg = result.yaw_deg;
    trial.executed = result.reachable;
    trial.success = result.success;
    trial.reason = result.reason;
    trial.final_error_m = result.place_error_m;
    trial.final_angle_deg = result.place_angle_deg;
    trial.ik_ms = result.planning_ms;
    trial.cycle_seconds = result.cycle_seconds;
    report.trials.push_back(trial);
    std::printf("demo: %s at (%.3f, %.3f, %.1f deg): %s%s%s\n", label.c_str(), trial.x, trial.y, trial.yaw_deg,
                trial.success ? "success" : (trial.executed ? "failed" : "skipped"), trial.reason.empty() ? "" : ": ",
                trial.reason.c_str());
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
    const vrrw_skills::PlanarPose planar = vrrw_skills::planarPose(s.object);
    track << s.time << "," << s.tcp.x() << "," << s.tcp.y() << "," << s.tcp.z() << "," << planar.x << "," << planar.y
          << "," << s.object.translation().z() << "," << planar.yaw << "\n";
  }
}
}  // namespace vrrw_evaluation
