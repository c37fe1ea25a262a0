#pragma once
#include <Eigen/Geometry>
#include <set>
#include <string>

namespace vrrw_skills
{
/// \brief What was seen of one pick-and-place in physics.
struct TrialObservation
{
  Eigen::Isometry3d object_start = Eigen::Isometry3d::Identity();  ///< before the first instruction
  Eigen::Isometry3d object_end = Eigen::Isometry3d::Identity();    ///< at rest after the gripper opened
  double max_lift = 0.0;               ///< m, highest rise of the object above its start while held
  bool gripper_open_at_end = false;    ///< the open_gripper goal succeeded
  std::set<std::string> arm_contacts;  ///< "link|body" pairs the arm touched, fingers excepted
  std::string failed_instruction;      ///< an instruction whose goal failed, with why; empty: none
};

/// \brief The success rule: lifted, carried, released within `final_radius` of the demonstrated
/// final position, no arm contact with the table or the object other than by the fingers.
struct SuccessCriteria
{
  double min_lift = 0.05;      ///< m
  double final_radius = 0.03;  ///< m, in the table plane
  double max_tilt_deg = 20.0;  ///< the object's z axis from the vertical at the end: more is toppled
};

struct TrialOutcome
{
  bool success = false;
  std::string reason;           ///< the first criterion that failed; empty on success
  double final_error_m = 0.0;   ///< object's end to the demonstrated end, table plane
  double final_angle_deg = 0.0; ///< yaw difference to the demonstrated end
};

/// \brief Judges a trial against the demonstrated end pose of the object.
TrialOutcome judgeTrial(const TrialObservation& seen, const Eigen::Isometry3d& demonstrated_end,
                        const SuccessCriteria& criteria = {});
/// \brief Position (table plane) and yaw differences of two object poses, m and deg.
double planarDistance(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double yawDifferenceDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
/// \brief The gripper's fingers may touch anything: links named *finger* or *knuckle*.
bool isFingerLink(const std::string& link);
/// \brief A contact pair that counts as a collision of `robot`'s arm with one of `obstacles`: one body
/// is a link of the robot (prefix "<robot>_") other than a finger, the other an obstacle.
bool isArmCollision(const std::string& body_a, const std::string& body_b, const std::string& robot,
                    const std::set<std::string>& obstacles);
}  // namespace vrrw_skills
