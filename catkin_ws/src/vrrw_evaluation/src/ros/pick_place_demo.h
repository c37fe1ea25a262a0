#pragma once
// The stages of ./vrrw demo on a running physics workspace: teach, replay, generalize.
#include <Eigen/Geometry>
#include <functional>
#include <string>
#include <vector>

#include <vrrw_evaluation/demo_report.h>
#include <vrrw_evaluation/demonstration.h>
#include <vrrw_skills/trial_poses.h>
#include <vrrw_evaluation/instruction_dmps.h>
#include <vrrw_evaluation/pick_place_task.h>

#include "ghost_operator.h"
#include "hand_operator.h"
#include "workspace_client.h"

namespace vrrw_evaluation
{
struct DemoOptions
{
  int trials = 20;
  std::uint64_t seed = 1;
  std::string out = "demo_report";
  int shown_trials = 2;             ///< DMP trials with a row of frames
  std::string capture_command;      ///< shell command with {file}: saves one rviz frame; empty: none
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
  /// and hand topics), the only ways the demonstration moves the arm.
  PickPlaceDemo(WorkspaceClient& client, GhostOperator& ghost, HandOperator& hand, DemoOptions options);

  /// \brief The scripted demonstration: near-pick, pick, close, back, carry and lower, open.
  bool teach(Demonstration& demo, DemoReport& report, std::string& error);
  /// \brief The six instructions as the demonstration's bag records them (its /demos/events annotations),
  /// replacing the script's own boundaries; false when the bag lacks one or has them out of order.
  bool segment(Demonstration& demo, DemoReport& report, std::string& error);
  /// \brief Direct imitation of every instruction from the reset scene; errors into `report`.
  bool replay(const Demonstration& demo, DemoReport& report, std::string& error);
  /// \brief DMPs per instruction, then `options.trials` new drill poses; one TrialRecord each.
  void generalize(const Demonstration& demo, DemoReport& report);

private:
  using Instruction = std::function<bool(std::string&)>;
  /// Runs the six instructions in order, recording; boundaries into `segments`, frames for `row`.
  bool perform(const std::string& row, bool frames, const std::vector<Instruction>& instructions,
               Recording& recording, std::vector<Segment>& segments, std::string& error);
  /// A straight TCP line through every pose of `legs` (each with its duration, minimum jerk), by IK (the
  /// runner's own moves between trials; the demonstration is the operator's).
  bool moveLinear(const std::vector<std::pair<Eigen::Isometry3d, double>>& legs, std::string& error);
  bool goHome(std::string& error);
  /// The final arm goal that releases the drill, as it is held now, where the demonstration released it.
  std::vector<double> placeGoal(const std::vector<double>& demonstrated, double& ik_ms);
  bool resetObject(const Eigen::Isometry3d& pose, std::string& error);
  void capture(const std::string& row, std::size_t boundary, bool frames);
  void writeRecording(const std::string& row, const Recording& recording, const std::vector<Segment>& segments);

  WorkspaceClient& client_;
  GhostOperator& ghost_;
  HandOperator& hand_;
  DemoOptions options_;
  std::vector<double> home_;
  Eigen::Isometry3d object_start_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d object_end_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d object_released_ = Eigen::Isometry3d::Identity();  ///< in the hand, before opening
  double demonstration_start_ = 0.0;  ///< s of ROS time: time 0 of the demonstration's recording
};
}  // namespace vrrw_evaluation
