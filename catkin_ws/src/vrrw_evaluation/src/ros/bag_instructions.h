#pragma once
// Stage 2 of ./vrrw demo: the instructions as the demonstration's bag records them.
#include <string>
#include <vector>
#include <utility>
#include <vrrw_evaluation/demonstration.h>

namespace vrrw_evaluation
{
/// \brief The instructions annotated in a recorded bag, in order, in s from `start_stamp` (the recording's
/// start, s of ROS time): /demos/events as the runner writes them (kind instruction_start / instruction_end,
/// detail the name) or as vrrw_demos' recorder does (kind annotate, text "instruction_start <name>").
/// Throws std::runtime_error naming the bag and what is wrong (unreadable, an instruction without its end).
std::vector<Segment> bagInstructions(const std::string& bag, double start_stamp);

/// \brief What a robot did in a recorded bag: its arm joints `arm_joints` from /<robot>/joint_states (s from
/// `start_stamp`) and its GripperCommand goals (/<robot>/gripper_controller/gripper_cmd/goal: position and
/// max_effort, in order). Throws std::runtime_error naming the bag and the topic when the arm is not in it.
struct BagTrack
{
  vrrw_trajectory::JointTrajectory arm;
  std::vector<std::pair<double, double>> gripper_goals;
};
BagTrack bagTrack(const std::string& bag, const std::string& robot, const std::vector<std::string>& arm_joints,
                  double start_stamp);
}  // namespace vrrw_evaluation
