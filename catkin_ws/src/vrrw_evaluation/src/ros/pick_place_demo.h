#pragma once
// The stages of ./vrrw demo on a running physics workspace: teach, replay, generalize.
#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <vrrw_demos/demonstration.h>
#include <vrrw_evaluation/demo_cell.h>
#include <vrrw_evaluation/demo_report.h>
#include <vrrw_evaluation/pick_place_task.h>
#include <vrrw_skills/skill.h>
#include <vrrw_skills/trial_poses.h>

#include "ghost_operator.h"
#include "hand_operator.h"
#include "workspace_client.h"

namespace vrrw_evaluation
{
/// One progress line of the demo, `demo: LINE`, flushed at once.
void progress(const std::string& line);

struct DemoOptions
{
  int trials = 20;
  std::uint64_t seed = 1;
  std::string out = "demo_report";
  int shown_trials = 2;             ///< skill trials with a row of frames
  std::string capture_command;      ///< program and arguments (no shell), {file} one of them: saves one rviz frame; empty: none
  GraspGeometry grasp;
  vrrw_skills::TrialSpread spread;
  Eigen::Vector2d final_offset{ -0.10, -0.25 };  ///< where the demonstration puts the drill, from its start
  std::string table = "table";                  ///< the scene object the drill is set down on
  /// the carry's ghost plans are minimum-jerk at this fraction of the acceleration limits: the drill, held by
  /// friction between two fingers, swings with steps in acceleration (see README)
  double carry_acceleration_scaling = 0.2;
  double descent_seconds = 1.2;  ///< the hand's pull from near-pick down to the grasp (free-drive)
};

class PickPlaceDemo
{
public:
  /// \brief `ghost` and `hand`: the operator's ghost-drive and free-drive (the interaction node's services
  /// and hand topics), the only ways the demonstration moves the arm. `cell`: the robot, the drill, the table and
  /// every object of the scene (stage 4's trials judge arm contacts with them).
  PickPlaceDemo(ros::NodeHandle& node, WorkspaceClient& client, GhostOperator& ghost, HandOperator& hand,
                const Cell& cell, DemoOptions options);

  /// \brief The scripted demonstration: near-pick, pick, close, back, carry and lower, open; recorded to
  /// demonstration.bag.
  bool teach(DemoReport& report, std::string& error);
  /// \brief Reads the demonstration back from its bag (vrrw_demos) and takes the six instructions as it records
  /// them (its /demos/events annotations); false when the bag lacks one or has them out of order.
  bool segment(DemoReport& report, std::string& error);
  /// \brief Direct imitation of every instruction from the reset scene; errors into `report`.
  bool replay(DemoReport& report, std::string& error);
  /// \brief `skill learn` on the bag, then `skill evaluate`'s trials on `options.trials` new drill poses.
  void generalize(DemoReport& report);

private:
  using Instruction = std::function<bool(std::string&)>;
  /// Runs the six instructions in order, recording; boundaries into `segments`, frames for `row`.
  bool perform(const std::string& row, bool frames, const std::vector<Instruction>& instructions,
               Recording& recording, std::vector<Segment>& segments, std::string& error);
  /// A straight TCP line through every pose of `legs` (each with its duration, minimum jerk), by IK (the
  /// runner's own moves between trials; the demonstration is the operator's).
  bool moveLinear(const std::vector<std::pair<Eigen::Isometry3d, double>>& legs, std::string& error);
  bool goHome(std::string& error);
  bool resetObject(const Eigen::Isometry3d& pose, std::string& error);
  void capture(const std::string& row, std::size_t boundary, bool frames);
  void writeRecording(const std::string& row, const Recording& recording, const std::vector<Segment>& segments);
  /// The skill learned from the bag into `report.skill`, compared with the script's grasp.
  vrrw_skills::Skill learnSkill(DemoReport& report);

  ros::NodeHandle& node_;
  WorkspaceClient& client_;
  GhostOperator& ghost_;
  HandOperator& hand_;
  Cell cell_;
  DemoOptions options_;
  std::vector<double> home_;
  Eigen::Isometry3d object_start_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d object_end_ = Eigen::Isometry3d::Identity();
  vrrw_demos::Demonstration shown_;    ///< the demonstration as its bag has it
  std::vector<Segment> instructions_;  ///< its annotated instructions, s from the recording's start
};
}  // namespace vrrw_evaluation
