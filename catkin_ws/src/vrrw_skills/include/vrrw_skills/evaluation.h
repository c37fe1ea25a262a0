#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <vrrw_skills/skill.h>
#include <vrrw_skills/trial_poses.h>

namespace vrrw_skills
{
/// \brief What `skill evaluate` is asked.
struct EvaluationOptions
{
  std::size_t trials = 20;
  std::uint64_t seed = 1;
  TrialSpread spread;  ///< around the demonstrated start: +-10 cm, +-10 cm, +-30 deg
  /// the most trials asked for at once (each takes seconds of physics)
  static constexpr std::size_t kMaxTrials = 1000;
};

/// \brief One trial: where the object stood, and how it ended.
struct TrialResult
{
  int trial = 0;  ///< from 1, as the progress lines count
  double x = 0.0, y = 0.0, yaw_deg = 0.0;  ///< the object's start, world
  bool reachable = false;     ///< every goal had a collision-free IK (the run started)
  bool success = false;
  double place_error_m = 0.0;     ///< the object's end to the demonstrated end, table plane
  double place_angle_deg = 0.0;   ///< its yaw to the demonstrated end's
  double cycle_seconds = 0.0;     ///< simulated, first goal to gripper open
  double planning_ms = 0.0;       ///< wall: IK, rollouts and checks of the run
  std::string reason;             ///< why it failed; empty on success
  std::vector<Eigen::Vector3d> tcp_path;  ///< the TCP, 10 Hz of simulated time, for the top view
  Eigen::Vector3d object_end = Eigen::Vector3d::Zero();
};

/// \brief Everything `skill evaluate` measured: metrics.json, index.html and the top view's data.
struct EvaluationReport
{
  std::string skill_file, scene, robot, taught_robot, object;
  EvaluationOptions options;
  CartesianPose object_start;  ///< the demonstrated start the poses are drawn around
  CartesianPose object_end;    ///< the demonstrated end the places are judged against
  double place_radius = 0.03;  ///< m
  std::vector<TrialResult> trials;
  double wall_seconds = 0.0;

  std::size_t successes() const;
  double successRate() const;
  /// \brief The fraction of trials whose every goal had a collision-free IK.
  double reachableRate() const;
};

/// \brief The trial poses: seeded draws around the skill's demonstrated object start (sampleTrialPoses).
std::vector<PlanarPose> evaluationPoses(const Skill& skill, const EvaluationOptions& options);

/// \brief metrics.json: trials, success_rate, failures [{trial, reason}], trial_results [{x, y, yaw_deg, success,
/// place_error_m, cycle_seconds, reason, ...}], wall_seconds, and more (reachable_rate, robot, planning_ms, ...).
std::string metricsJson(const EvaluationReport& report);
/// \brief The JSON line the tool prints last: the keys of metrics.json without trial_results' paths.
std::string summaryJson(const EvaluationReport& report);
/// \brief index.html: the figures, a table of the trials and the top view (top_view.png beside it).
std::string indexHtml(const EvaluationReport& report);
/// \brief tracks.json, what the plot script draws the top view from: the demonstrated start and end, the place
/// radius, per trial its start, end and TCP path.
std::string tracksJson(const EvaluationReport& report);
}  // namespace vrrw_skills
