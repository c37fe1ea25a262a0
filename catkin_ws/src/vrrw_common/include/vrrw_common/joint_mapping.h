#pragma once
// The one lookup from a message's joint names (JointState, JointTrajectory, a goal) to a robot's joint order.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace vrrw_common
{
/// \brief A message's joint names that do not fit the robot's; what() is one line naming the joints, joint()
/// and reason() the first of them for a caller that words its own error (`joint_names`, `goal_joints`).
class JointMappingError : public std::invalid_argument
{
public:
  JointMappingError(const std::string& what, std::string joint, std::string reason)
    : std::invalid_argument(what), joint_(std::move(joint)), reason_(std::move(reason))
  {
  }
  /// \brief The (first) joint at fault.
  const std::string& joint() const { return joint_; }
  /// \brief "missing", "named twice", "not a joint of the robot" or "no value".
  const std::string& reason() const { return reason_; }

private:
  std::string joint_, reason_;
};

/// \brief What to do with names of a message that the robot does not have.
enum class OtherJoints
{
  Skip,   ///< a JointState of several robots, a gripper's joint beside the arm's
  Refuse  ///< a goal must name the robot's joints and only those
};

/// \brief Where each of the robot's joints stands in a message.
///
/// Example: a robot with the joints (its own order)
///     wanted = {pan, lift, elbow}
/// gets a JointState naming
///     given  = {elbow, pan, finger, lift}
/// The mapping is {1, 3, 0}: wanted[i] is given[mapping[i]], so the robot's positions are
///     {position[1], position[3], position[0]}.
/// Names in \a given that the robot does not have (`finger`) are skipped, or refused with OtherJoints::Refuse.
/// A name of \a wanted missing from \a given, or one of the robot's names given (or wanted) twice, is refused:
/// `joint names: missing elbow, lift` / `joint names: pan named twice` / `joint names: finger is not a joint of
/// the robot`.
std::vector<std::size_t> jointMapping(const std::vector<std::string>& given, const std::vector<std::string>& wanted,
                                      OtherJoints others = OtherJoints::Skip);

/// \brief The same without the error: empty when a wanted joint is missing or a name is doubled (for a
/// callback that skips messages of other robots).
std::optional<std::vector<std::size_t>> findJoints(const std::vector<std::string>& given,
                                                    const std::vector<std::string>& wanted);

/// \brief The values of the robot's joints (\a wanted) from a message's \a names and \a values, in the robot's
/// order; empty when a wanted joint is missing, doubled or has no value (`state.position` of a JointState).
std::optional<std::vector<double>> findValues(const std::vector<std::string>& names, const std::vector<double>& values,
                                              const std::vector<std::string>& wanted);

/// \brief For a message naming some of the robot's joints (a partial goal), where each of them stands in the
/// robot: given = {elbow, pan} of the robot {pan, lift, elbow} gives {2, 0}. A name the robot does not have,
/// or one given twice, is refused (`joint names: finger is not a joint of the robot`).
std::vector<std::size_t> robotIndices(const std::vector<std::string>& given, const std::vector<std::string>& robot);

/// \brief values[mapping[i]] for every i: a message's values in the robot's order. An empty \a values (a
/// JointState without velocities) gives an empty result; a shorter one is refused naming \a field.
std::vector<double> inRobotOrder(const std::vector<double>& values, const std::vector<std::size_t>& mapping,
                                 const std::string& field = "position");
}  // namespace vrrw_common
