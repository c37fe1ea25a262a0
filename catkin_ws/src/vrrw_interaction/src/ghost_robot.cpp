#include <vrrw_interaction/ghost_robot.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <vrrw_common/joint_mapping.h>

namespace vrrw_interaction
{
using vrrw_kinematics::ErrorCode;

namespace
{
std::string fixed(double value, int digits)
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << value;
  return out.str();
}

/// A residual in at most a dozen characters: millimetres in the workspace, powers of ten far outside it.
std::string residual(double value, const char* unit)
{
  if (std::abs(value) < 1e3)
    return fixed(value, 3) + " " + unit;
  std::ostringstream out;
  out << std::setprecision(3) << value << " " << unit;
  return out.str();
}

/// Holds the place contact allowed for one check or plan.
class PlaceContact
{
public:
  explicit PlaceContact(const std::function<void(bool)>& allow) : allow_(allow)
  {
    if (allow_)
      allow_(true);
  }
  ~PlaceContact()
  {
    if (allow_)
      allow_(false);
  }
  PlaceContact(const PlaceContact&) = delete;
  PlaceContact& operator=(const PlaceContact&) = delete;

private:
  const std::function<void(bool)>& allow_;
};

}  // namespace

std::string ikRefusal(const vrrw_kinematics::IkResult& ik)
{
  switch (ik.code)
  {
    case ErrorCode::NoSolution:
      return "unreachable (residual " + residual(ik.position_error, "m") + ", " + residual(ik.orientation_error, "rad") + ")";
    case ErrorCode::JointJump:
      return "joint jump " + fixed(ik.jump, 2) + " rad (a branch flip; move the marker in smaller steps)";
    case ErrorCode::InCollision:
      return "collision: " + ik.contact.body_a + " - " + ik.contact.body_b;
    default:
      return ik.message;
  }
}

GhostRobot::GhostRobot(vrrw_kinematics::Arm& arm, Presets presets, const Eigen::VectorXd& q)
  : arm_(arm), presets_(std::move(presets)), q_(q)
{
}

Eigen::Isometry3d GhostRobot::tcpPose(const Eigen::VectorXd& world_state)
{
  return arm_.basePose(world_state) * arm_.ikSolver().chain().fk(q_);
}

// The ghost only ever stands where the robot could: within its limits and free of collision (the place contact
// allowed while a held object is set down).
Outcome GhostRobot::moveTo(const Eigen::VectorXd& q, const Eigen::VectorXd& world_state, const std::string& what)
{
  if (const std::string violation = arm_.bounds().violation(q); !violation.empty())
    return { false, what + ": " + violation };
  vrrw_kinematics::Contact contact;
  {
    const PlaceContact place(place_contact);
    contact = arm_.check(q, world_state);
  }
  if (contact.collision)
    return { false, what + ": collision: " + contact.body_a + " - " + contact.body_b };
  q_ = q;
  return { true, what };
}

Outcome GhostRobot::setJoints(const std::vector<std::string>& names, const std::vector<double>& positions,
                              const Eigen::VectorXd& world_state)
{
  const std::vector<std::string>& joints = arm_.jointNames();
  Eigen::VectorXd q = q_;
  if (names.empty())  // every joint, in the arm's own order
  {
    if (positions.size() != joints.size())
      return { false, "position: " + std::to_string(positions.size()) + " values, the arm has " +
                          std::to_string(joints.size()) + " joints" };
    for (std::size_t i = 0; i < positions.size(); ++i)
      q[static_cast<Eigen::Index>(i)] = positions[i];
  }
  else  // some joints by name (the others keep their values); a name twice is refused, as /<robot>/plan does
  {
    if (names.size() != positions.size())
      return { false, "name/position: " + std::to_string(names.size()) + " names but " +
                          std::to_string(positions.size()) + " positions" };
    std::vector<std::size_t> at;
    try
    {
      at = vrrw_common::robotIndices(names, joints);
    }
    catch (const vrrw_common::JointMappingError& e)
    {
      return { false, "name: '" + e.joint() + "' " +
                          (e.reason() == "named twice" ? e.reason() : "is not an arm joint of " + arm_.robot().name) };
    }
    for (std::size_t i = 0; i < at.size(); ++i)
      q[static_cast<Eigen::Index>(at[i])] = positions[i];
  }
  for (Eigen::Index i = 0; i < q.size(); ++i)
    if (!std::isfinite(q[i]))
      return { false, "position: joint " + joints[static_cast<std::size_t>(i)] + " is not finite" };
  return moveTo(q, world_state, "set_joints");
}

Outcome GhostRobot::setPose(const Eigen::Isometry3d& target, const Eigen::VectorXd& world_state, double max_jump,
                            Eigen::Vector2d* residual)
{
  vrrw_kinematics::IkOptions options;
  options.max_jump = max_jump;
  options.timeout = 0.003;  // numeric chains at drag rate; a closed form answers in microseconds
  vrrw_kinematics::IkResult ik;
  {
    const PlaceContact place(place_contact);
    ik = arm_.solveCollisionFree(target, q_, world_state, options);
  }
  if (residual)
    *residual = Eigen::Vector2d(ik.position_error, ik.orientation_error);
  if (!ik.success)
    return { false, ikRefusal(ik) };
  q_ = ik.q;
  return { true, "set_pose" };
}

Outcome GhostRobot::preset(const std::string& name, const Eigen::VectorXd& world_state)
{
  if (!presets_.has(name))
  {
    try
    {
      presets_.at(name);
    }
    catch (const PresetError& e)
    {
      return { false, e.what() };
    }
  }
  // A preset is a named joint pose and is taken as it is (the paper's zero stretches a table-mounted UR
  // into the table): only limits refuse it; a collision is reported, and planning to it will refuse.
  const Eigen::VectorXd& q = presets_.at(name);
  if (const std::string violation = arm_.bounds().violation(q); !violation.empty())
    return { false, "preset " + name + ": " + violation };
  q_ = q;
  if (const vrrw_kinematics::Contact contact = arm_.check(q, world_state); contact.collision)
    return { true, "preset " + name + " (in collision: " + contact.body_a + " - " + contact.body_b + ")" };
  return { true, "preset " + name };
}

Outcome GhostRobot::reset(const Eigen::VectorXd& world_state)
{
  q_ = arm_.jointValues(world_state);
  return { true, "reset: the ghost is at the robot" };
}

Outcome GhostRobot::addWaypoint()
{
  waypoints_.push_back(q_);
  return { true, "waypoint " + std::to_string(waypoints_.size() - 1) + " added (" +
                     std::to_string(waypoints_.size()) + " in all)" };
}

Outcome GhostRobot::clearWaypoints()
{
  const std::size_t count = waypoints_.size();
  waypoints_.clear();
  return { true, std::to_string(count) + " waypoints cleared" };
}

vrrw_kinematics::TrajectoryResult GhostRobot::plan(const Eigen::VectorXd& world_state, double time_limit,
                                                   const vrrw_kinematics::SpeedScaling& scaling,
                                                   vrrw_kinematics::TimeProfile profile)
{
  // From where the robot is now (not the ghost) through the waypoints to the ghost.
  vrrw_kinematics::TrajectoryRequest request;
  request.scaling = scaling;
  request.profile = profile;
  request.plan.start = arm_.jointValues(world_state);
  request.plan.goal_joints = q_;
  request.plan.time_limit = time_limit > 0.0 ? time_limit : 1.0;
  request.waypoints = waypoints_;
  vrrw_kinematics::TrajectoryResult result;
  if (!place_contact || waypoints_.empty())
  {
    const PlaceContact place(place_contact);
    result = arm_.planTrajectory(request, world_state);
  }
  else
  {
    // to the last waypoint as always (its index keeps its meaning), then the place leg with the contact allowed
    vrrw_kinematics::TrajectoryRequest place_leg = request;
    request.plan.goal_joints = waypoints_.back();
    request.waypoints.pop_back();
    place_leg.plan.start = waypoints_.back();
    place_leg.waypoints.clear();
    result = arm_.planTrajectory(request, world_state);
    if (result.success)
    {
      const PlaceContact place(place_contact);
      vrrw_kinematics::TrajectoryResult last = arm_.planTrajectory(place_leg, world_state);
      if (last.success)
        vrrw_kinematics::appendTrajectory(result, last);
      else
        result = last, result.failed_waypoint = result.failed_waypoint < 0 ? -1 : int(waypoints_.size());
    }
  }
  if (result.success)
    last_plan_ = result.trajectory;
  return result;
}
}  // namespace vrrw_interaction
