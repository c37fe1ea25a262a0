#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <vrrw_demos/segmentation.h>

namespace vrrw_evaluation
{
/// \brief The demo's instructions are vrrw_demos' (the annotated spans of the demonstration's bag).
using vrrw_demos::Segment;

/// \brief What stage 4 learned: the skill `./vrrw skill learn` writes from the demonstration's bag.
struct LearnedSkillReport
{
  std::string file;            ///< skill.yaml in the report
  double learn_seconds = 0.0;  ///< wall: reading the bag and learning
  double grasp_learned[3] = { 0.0, 0.0, 0.0 };  ///< m, the TCP at the grasp in the drill's frame, as learned
  double grasp_taught[3] = { 0.0, 0.0, 0.0 };   ///< ... as the teach script meant it (GraspGeometry)
  double grasp_error_mm = 0.0;   ///< distance between the two
  double grasp_error_deg = 0.0;  ///< angle between their orientations
  std::map<std::string, double> cartesian_fit_rmse_m;    ///< per arm instruction
  std::map<std::string, double> cartesian_fit_rmse_deg;  ///< per arm instruction
};
/// \brief One generalization trial: where the object stood, and how it ended.
struct TrialRecord
{
  int trial = 0;
  double x = 0.0, y = 0.0, yaw_deg = 0.0;  ///< the object's start (world)
  bool executed = false;  ///< false: skipped (unreachable or colliding pose)
  bool success = false;
  std::string reason;
  double final_error_m = 0.0;
  double final_angle_deg = 0.0;
  double ik_ms = 0.0;  ///< planning the run: every IK, rollout and collision check of the trial
  double cycle_seconds = 0.0;  ///< simulated, first goal to the gripper open
};

/// \brief Everything `./vrrw demo` measured; written as metrics.json, report.md and index.html.
struct DemoReport
{
  std::string scene;
  std::string teach_source;  ///< how the demonstration was made
  std::uint64_t seed = 0;
  double teach_seconds = 0.0;
  double teach_start_stamp = 0.0;  ///< s of ROS time at the recording's start: segment times count from it
  /// Per instruction in order: the interfaces the scripted operator used (topics, services, actions).
  std::vector<std::pair<std::string, std::vector<std::string>>> teach_interfaces;
  std::uint64_t bag_messages = 0;
  std::string bag_file;  ///< the demonstration's bag
  std::map<std::string, std::uint64_t> message_counts;  ///< per topic
  std::vector<Segment> segments;
  double replay_joint_rms_rad = 0.0;
  std::map<std::string, double> replay_segment_rms_rad;
  double replay_object_position_error_m = 0.0;
  double replay_object_angle_error_deg = 0.0;
  std::map<std::string, double> dmp_fit_rmse_rad;  ///< the skill's joint DMPs, per arm instruction
  LearnedSkillReport skill;
  std::vector<TrialRecord> trials;
  double plan_ms = 0.0;      ///< planning time of the teach stage's planned motions
  double physics_rtf = 0.0;  ///< simulated seconds per wall second
  std::map<std::string, double> stage_seconds;
  double wall_seconds = 0.0;

  int trialCount() const { return int(trials.size()); }
  int successCount() const;
  double successRate() const;
};

/// \brief `text` as a JSON string: quoted, with quotes, backslashes and newlines escaped.
std::string jsonString(const std::string& text);
/// \brief metrics.json (the keys, dots as nesting, and more).
std::string metricsJson(const DemoReport& report);
/// \brief report.md: the metrics table and the trials.
std::string reportMarkdown(const DemoReport& report);
/// \brief index.html: the same with the frame strips and plots the plot script draws beside it.
std::string reportHtml(const DemoReport& report);
/// \brief Writes the three into `directory` (created); throws std::runtime_error naming a file it cannot write.
void writeReport(const DemoReport& report, const std::string& directory);
}  // namespace vrrw_evaluation
