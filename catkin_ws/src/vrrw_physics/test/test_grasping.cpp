// Grasping by contact: the UR5e + Robotiq 2F-85 closes on an object, lifts it 20 cm and carries
// it 30 cm sideways; friction alone holds it (no grasp-assist constraint, no teleporting).
#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace vrrw_physics;

namespace
{

vrrw_scene::Scene scene(const std::string& name)
{
  vrrw_scene::LoadOptions options;
  options.root = VRRW_TEST_ROOT;
  return vrrw_scene::loadScene(name, options);
}

/// Damped least squares on a kinematic copy of the robot (numerical Jacobian of the TCP pose;
/// Bullet's frames are single precision, so steps of 1e-4 rad and a 1e-5 tolerance).
class Ik
{
public:
  Ik(const vrrw_scene::Scene& cell, const vrrw_scene::Robot& spec)
    : spec_(spec), model_(urdf::parseURDF(cell.urdf)), robot_(*model_, spec.name, spec.base_link)
  {
    for (const auto& joint : spec.arm_joints)
      index_.push_back(std::size_t(robot_.jointIndex(joint)));
  }

  std::vector<double> solve(const Eigen::Isometry3d& goal, std::vector<double> q, bool* converged = nullptr)
  {
    for (int iteration = 0; iteration < 200; ++iteration)
    {
      const Eigen::Matrix<double, 6, 1> e = error(goal, q);
      if (e.norm() < 1e-5)
      {
        for (double& angle : q)
          angle = std::remainder(angle, 2 * M_PI);
        if (converged)
          *converged = true;
        return q;
      }
      Eigen::Matrix<double, 6, 6> jacobian;
      for (int j = 0; j < 6; ++j)
      {
        std::vector<double> dq = q;
        dq[std::size_t(j)] += 1e-4;
        jacobian.col(j) = (e - error(goal, dq)) / 1e-4;
      }
      const Eigen::Matrix<double, 6, 6> jjt = jacobian * jacobian.transpose() + 1e-6 * Eigen::Matrix<double, 6, 6>::Identity();
      const Eigen::Matrix<double, 6, 1> step = jacobian.transpose() * jjt.ldlt().solve(e);
      for (int j = 0; j < 6; ++j)
        q[std::size_t(j)] += step(j);
    }
    if (!converged)
      ADD_FAILURE() << "IK did not converge";
    return q;
  }

private:
  Eigen::Matrix<double, 6, 1> error(const Eigen::Isometry3d& goal, const std::vector<double>& arm)
  {
    std::vector<double> q(robot_.joints().size(), 0.0);
    for (std::size_t j = 0; j < 6; ++j)
      q[index_[j]] = arm[j];
    robot_.setState(q, std::vector<double>(q.size(), 0.0));
    const Eigen::Isometry3d tcp = robot_.linkPose(spec_.tcp_link);
    const Eigen::AngleAxisd rotation(goal.rotation() * tcp.rotation().transpose());
    Eigen::Matrix<double, 6, 1> e;
    e << goal.translation() - tcp.translation(), rotation.angle() * rotation.axis();
    return e;
  }

  vrrw_scene::Robot spec_;
  urdf::ModelInterfaceSharedPtr model_;
  ArticulatedRobot robot_;
  std::vector<std::size_t> index_;
};

/// Streams joint targets (position and velocity) to the arm and the gripper: min-jerk in joint
/// space, or along a straight TCP line (min-jerk in time, IK every 10 ms).
class Operator
{
public:
  Operator(PhysicsWorld& world, Ik& ik, const vrrw_scene::Robot& spec)
    : world_(world), ik_(ik), spec_(spec), tcp_(world.framePose(spec.tcp_link))
  {
    const auto state = world.jointStates(spec.name);
    for (const auto& joint : spec.arm_joints)
      arm_.push_back(state.position[std::size_t(world.robot(spec.name).jointIndex(joint))]);
  }

  const std::vector<double>& arm() const { return arm_; }
  /// \brief Force limit of the finger drive from now on (N m; 0: the configured one).
  void setFingerEffort(double effort) { finger_effort_ = effort; }

  /// Moves the TCP along a straight line (orientation by slerp) to `goal` over `seconds`.
  void moveLinear(const Eigen::Isometry3d& goal, double seconds, const std::function<void()>& check = {})
  {
    const double sample = 0.01;
    const int samples = int(std::lround(seconds / sample));
    std::vector<std::vector<double>> q{ arm_ };
    const Eigen::Quaterniond from_rotation(tcp_.rotation()), to_rotation(goal.rotation());
    for (int k = 1; k <= samples; ++k)
    {
      const double s = double(k) / samples;
      const double blend = s * s * s * (10 - 15 * s + 6 * s * s);
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = tcp_.translation() + blend * (goal.translation() - tcp_.translation());
      pose.linear() = from_rotation.slerp(blend, to_rotation).toRotationMatrix();
      q.push_back(ik_.solve(pose, q.back()));
    }
    const int per_sample = int(std::lround(sample / world_.options().dt));
    for (int k = 0; k < samples; ++k)
      for (int i = 1; i <= per_sample; ++i)
      {
        std::vector<double> target(6), rate(6);
        for (std::size_t j = 0; j < 6; ++j)
        {
          rate[j] = (q[std::size_t(k + 1)][j] - q[std::size_t(k)][j]) / sample;
          target[j] = q[std::size_t(k)][j] + rate[j] * i * world_.options().dt;
        }
        world_.setDriveTargets(spec_.name, spec_.arm_joints, target, rate);
        world_.setDriveTargets(spec_.name, spec_.gripper_joints, { finger_ }, { 0.0 }, { finger_effort_ });
        ASSERT_TRUE(world_.step()) << world_.lastError();
        if (check)
          check();
      }
    arm_ = q.back();
    tcp_ = goal;
  }

  /// Moves arm and finger to new targets over `seconds`, calling `check` after every step.
  void move(const std::vector<double>& arm, double finger, double seconds, const std::function<void()>& check = {})
  {
    const std::vector<double> from = arm_;
    const double finger_from = finger_;
    const int steps = int(std::lround(seconds / world_.options().dt));
    for (int i = 1; i <= steps; ++i)
    {
      const double s = double(i) / steps;
      const double blend = s * s * s * (10 - 15 * s + 6 * s * s);
      const double rate = 30 * s * s * (1 - s) * (1 - s) / seconds;
      std::vector<double> q(6), qd(6);
      for (std::size_t j = 0; j < 6; ++j)
      {
        q[j] = from[j] + blend * (arm[j] - from[j]);
        qd[j] = rate * (arm[j] - from[j]);
      }
      world_.setDriveTargets(spec_.name, spec_.arm_joints, q, qd);
      world_.setDriveTargets(spec_.name, spec_.gripper_joints, { finger_from + blend * (finger - finger_from) },
                             { rate * (finger - finger_from) }, { finger_effort_ });
      ASSERT_TRUE(world_.step()) << world_.lastError();
      if (check)
        check();
    }
    arm_ = arm;
    finger_ = finger;
    tcp_ = world_.framePose(spec_.tcp_link);
  }

private:
  PhysicsWorld& world_;
  Ik& ik_;
  vrrw_scene::Robot spec_;
  Eigen::Isometry3d tcp_;
  std::vector<double> arm_;
  double finger_ = 0.0;
  double finger_effort_ = 0.0;
};

struct GraspResult
{
  double max_slip = 1e9;     ///< mm, largest move of the grasp point in the TCP frame since the lift began
  double max_offset = 1e9;   ///< mm, grasp point to TCP, while lifting and carrying
  double lifted = 0.0;       ///< m, rise of the grasp point from where the gripper closed on it
  double carried = 0.0;      ///< m, its travel along the carry direction
};

/// Grasps `object` at `grasp` (a point in the object frame) with the TCP in orientation `tool`
/// (world), approaching along the tool z axis; lifts 0.2 m and carries it by `carry` (world).
GraspResult pickAndCarry(PhysicsWorld& world, const vrrw_scene::Scene& cell, const std::string& robot,
                         const std::string& object, const Eigen::Vector3d& grasp, const Eigen::Matrix3d& tool,
                         const Eigen::Vector3d& carry, double closed)
{
  const vrrw_scene::Robot& spec = *std::find_if(cell.robots.begin(), cell.robots.end(),
                                                [&](const vrrw_scene::Robot& r) { return r.name == robot; });
  Ik ik(cell, spec);
  Operator op(world, ik, spec);
  const Eigen::Vector3d start = world.objectPose(object) * grasp;
  auto pose = [&](const Eigen::Vector3d& p) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = tool;
    t.translation() = p;
    return t;
  };
  const Eigen::Vector3d approach = -0.12 * tool.col(2);
  op.moveLinear(pose(start + approach), 2.0);
  op.moveLinear(pose(start), 1.0);
  op.move(op.arm(), closed, 1.0);
  op.move(op.arm(), closed, 0.5);
  GraspResult result;
  result.max_offset = 0.0;
  result.max_slip = 0.0;
  const Eigen::Vector3d held = world.framePose(spec.tcp_link).inverse() * (world.objectPose(object) * grasp);
  const Eigen::Vector3d gripped = world.objectPose(object) * grasp;
  auto check = [&] {
    const Eigen::Vector3d in_tcp = world.framePose(spec.tcp_link).inverse() * (world.objectPose(object) * grasp);
    result.max_offset = std::max(result.max_offset, 1000.0 * in_tcp.norm());
    result.max_slip = std::max(result.max_slip, 1000.0 * (in_tcp - held).norm());
  };
  const Eigen::Vector3d lifted = start + Eigen::Vector3d(0, 0, 0.2);
  const Eigen::Vector3d carried = lifted + carry;
  op.moveLinear(pose(lifted), 1.5, check);
  op.moveLinear(pose(carried), 2.0, check);
  op.move(op.arm(), closed, 0.5, check);
  const Eigen::Vector3d end = world.objectPose(object) * grasp;
  result.lifted = end.z() - gripped.z();
  result.carried = (end - gripped).dot(carry.normalized());
  return result;
}

vrrw_scene::Object cube(double size, const Eigen::Vector3d& position)
{
  vrrw_scene::Object o;
  o.name = "small_cube";
  o.kind = "cube";
  vrrw_scene::Shape box;
  box.type = vrrw_scene::Shape::Type::Box;
  box.box_size = Eigen::Vector3d::Constant(size);
  o.collision.push_back(box);
  o.mass = 0.2;
  o.inertia = Eigen::Matrix3d::Identity() * 0.2 * size * size / 6.0;
  o.friction = 0.8;
  o.pose.translation() = position + Eigen::Vector3d(0, 0, size / 2);
  return o;
}
}  // namespace

TEST(Grasping, Ur5eWith2F85LiftsAndCarriesACubeByFriction)
{
  vrrw_scene::Scene cell = scene("pick_place_drill");
  // The 2F-85 opens to 85 mm: the shipped 10 cm cube does not fit, a 6 cm one does.
  cell.objects.erase(std::remove_if(cell.objects.begin(), cell.objects.end(),
                                    [](const vrrw_scene::Object& o) { return o.name != "table"; }),
                     cell.objects.end());
  cell.objects.push_back(cube(0.06, Eigen::Vector3d(0.05, -0.1, 0.75)));
  PhysicsWorld world(cell);
  Eigen::Matrix3d down;
  down.col(0) = Eigen::Vector3d(-1, 0, 0);
  down.col(1) = Eigen::Vector3d(0, 1, 0);
  down.col(2) = Eigen::Vector3d(0, 0, -1);
  const GraspResult r =
      pickAndCarry(world, cell, "ur5e", "small_cube", Eigen::Vector3d::Zero(), down, Eigen::Vector3d(0, 0.3, 0), 0.8);
  std::cout << "cube: lifted " << r.lifted << " m, carried " << r.carried << " m, centre within " << r.max_offset
            << " mm of the TCP, slipped " << r.max_slip << " mm\n";
  EXPECT_NEAR(r.lifted, 0.2, 0.005);
  EXPECT_NEAR(r.carried, 0.3, 0.005);
  // the README's target is 5 mm; deterministic: centre 0.216 mm from the TCP, 0.346 mm slip measured (0.114 mm,
  // 0.170 mm before issue 22's solver order)
  EXPECT_LT(r.max_offset, 0.35);
  EXPECT_LT(r.max_slip, 0.5);
}

TEST(Grasping, Ur5eWith2F85LiftsAndCarriesTheDrillByItsBody)
{
  const vrrw_scene::Scene cell = scene("pick_place_drill");
  PhysicsWorld world(cell);
  for (int i = 0; i < 200; ++i)
    world.step();  // let the drill settle on the table
  // From above, fingers across the 64 mm motor housing just ahead of the grip, over the centre of
  // mass: the grip itself sits under the housing, where a top-down 2F-85 cannot reach and a side
  // approach puts the UR5e's wrist on the table.
  const Eigen::Matrix3d drill = world.objectPose("drill").rotation();
  Eigen::Matrix3d down;
  down.col(2) = Eigen::Vector3d(0, 0, -1);
  down.col(1) = drill.col(1);
  down.col(0) = down.col(1).cross(down.col(2));
  // Carried towards -y: 0.3 m further out along +y is beyond the UR5e's reach with the tool down.
  const GraspResult r =
      pickAndCarry(world, cell, "ur5e", "drill", Eigen::Vector3d(0.03, 0.0, 0.203), down, Eigen::Vector3d(0, -0.3, 0), 0.8);
  std::cout << "drill: lifted " << r.lifted << " m, carried " << r.carried << " m, grasp point within "
            << r.max_offset << " mm of the TCP, slipped " << r.max_slip << " mm\n";
  EXPECT_NEAR(r.lifted, 0.2, 0.005);
  EXPECT_NEAR(r.carried, 0.3, 0.005);
  // The TCP is the pad centre of the closed gripper; on the 64 mm housing the pads sit lower along
  // the tool axis, so the grasp point is judged by how far it slips in the TCP frame: 0.276 mm measured
  // (target 5 mm).
  EXPECT_LT(r.max_slip, 0.8);
}

TEST(Grasping, Ur5eWith2F85HoldsTheDrillAtSixPlacements)
{
  // The drill moved on the table (x, y in m, yaw in rad about its own z), each taken the same way from above and
  // carried 0.3 m towards -y: the grip must not depend on one lucky placement.
  const std::vector<Eigen::Vector3d> placements = { { 0.0, 0.0, 0.0 },    { 0.05, 0.0, 0.0 },  { -0.05, 0.0, 0.0 },
                                                    { 0.0, 0.05, 0.3 },   { 0.0, -0.05, -0.3 }, { 0.03, 0.03, 0.5 } };
  double worst = 0.0;
  for (const Eigen::Vector3d& p : placements)
  {
    vrrw_scene::Scene cell = scene("pick_place_drill");
    for (vrrw_scene::Object& o : cell.objects)
      if (o.name == "drill")
      {
        o.pose.translation() += Eigen::Vector3d(p.x(), p.y(), 0.0);
        o.pose.linear() = Eigen::AngleAxisd(p.z(), Eigen::Vector3d::UnitZ()) * o.pose.linear();
      }
    PhysicsWorld world(cell);
    for (int i = 0; i < 200; ++i)
      world.step();
    const Eigen::Matrix3d drill = world.objectPose("drill").rotation();
    Eigen::Matrix3d down;
    down.col(2) = Eigen::Vector3d(0, 0, -1);
    down.col(1) = drill.col(1);
    down.col(0) = down.col(1).cross(down.col(2));
    const GraspResult r = pickAndCarry(world, cell, "ur5e", "drill", Eigen::Vector3d(0.03, 0.0, 0.203), down,
                                       Eigen::Vector3d(0, -0.3, 0), 0.8);
    std::cout << "drill at +" << p.x() << " m x, +" << p.y() << " m y, " << p.z() << " rad: lifted " << r.lifted
              << " m, carried " << r.carried << " m, slipped " << r.max_slip << " mm\n";
    EXPECT_NEAR(r.lifted, 0.2, 0.005) << p.transpose();
    EXPECT_NEAR(r.carried, 0.3, 0.005) << p.transpose();
    worst = std::max(worst, r.max_slip);
  }
  std::cout << "six placements: largest slip " << worst << " mm\n";
  // deterministic: 0.12-1.14 mm measured with the joint rows after the contacts (issue 22), 0.27-0.57 mm before
  // (target 5 mm)
  EXPECT_LT(worst, 2.0);
}

TEST(Grasping, Ur10eWith2F140LiftsAndCarriesThe10cmCube)
{
  // The shipped 10 cm cube of paper_multibot fits the 2F-140 (140 mm stroke), not the 2F-85.
  const vrrw_scene::Scene cell = scene("paper_multibot");
  PhysicsWorld world(cell);
  // The UR5e's gripper hangs over the cube at home: stand its arm up first.
  world.setDriveTargets("ur5e", { "ur5e_elbow_joint" }, { 0.0 }, {});
  for (int i = 0; i < 3000; ++i)
    ASSERT_TRUE(world.step()) << world.lastError();
  Eigen::Matrix3d down;
  down.col(0) = Eigen::Vector3d(-1, 0, 0);
  down.col(1) = Eigen::Vector3d(0, 1, 0);
  down.col(2) = Eigen::Vector3d(0, 0, -1);
  const GraspResult r =
      pickAndCarry(world, cell, "ur10e", "cube", Eigen::Vector3d(0, 0, 0.05), down, Eigen::Vector3d(0, 0.3, 0), 0.7);
  std::cout << "10 cm cube (UR10e + 2F-140): lifted " << r.lifted << " m, carried " << r.carried
            << " m, centre within " << r.max_offset << " mm of the TCP, slipped " << r.max_slip << " mm\n";
  EXPECT_NEAR(r.lifted, 0.2, 0.005);
  EXPECT_NEAR(r.carried, 0.3, 0.005);
  EXPECT_LT(r.max_slip, 0.008);  // deterministic: 0.0024 mm measured (0.41 mm before issue 22's solver order; target 5 mm)
}

namespace
{
struct HeldLoad
{
  double error = 0.0;         ///< rad, largest |q - target| of the shoulder lift and elbow after the hold
  double worst = 0.0;         ///< rad, largest |q - target| of all six arm joints then
  std::string worst_joint;
  std::vector<std::string> held;  ///< what the world judged held then
};

/// The drill picked as above, lifted 0.2 m, then the arm stretched out (upper arm 0.8 rad above horizontal,
/// forearm level, about 0.7 m from the shoulder axis) over 2 s and held there for 2 s, squeezed with `grip` N
/// per pad (GripperCommand max_effort on the 2F-85: x 0.0182 m of lever arm).
HeldLoad holdDrillStretched(const WorldOptions& options, double grip = 70.0)
{
  const vrrw_scene::Scene cell = scene("pick_place_drill");
  PhysicsWorld world(cell, options);
  for (int i = 0; i < 200; ++i)
    world.step();
  const vrrw_scene::Robot& spec = cell.robots.front();
  Ik ik(cell, spec);
  Operator op(world, ik, spec);
  op.setFingerEffort(grip * 0.0182);
  const Eigen::Matrix3d drill = world.objectPose("drill").rotation();
  Eigen::Matrix3d down;
  down.col(2) = Eigen::Vector3d(0, 0, -1);
  down.col(1) = drill.col(1);
  down.col(0) = down.col(1).cross(down.col(2));
  const Eigen::Vector3d start = world.objectPose("drill") * Eigen::Vector3d(0.03, 0.0, 0.203);
  auto pose = [&](const Eigen::Vector3d& p) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = down;
    t.translation() = p;
    return t;
  };
  op.moveLinear(pose(start - 0.12 * down.col(2)), 2.0);
  op.moveLinear(pose(start), 1.0);
  op.move(op.arm(), 0.8, 1.0);
  op.move(op.arm(), 0.8, 0.5);
  op.moveLinear(pose(start + Eigen::Vector3d(0, 0, 0.2)), 1.5);
  std::vector<double> stretched = op.arm();
  stretched[1] = -0.8;
  stretched[2] = 0.8;
  stretched[3] = -M_PI / 2;  // the tool stays pointing down
  op.move(stretched, 0.8, 2.0);
  op.move(stretched, 0.8, 2.0);
  HeldLoad out;
  const ArticulatedRobot& robot = world.robot(spec.name);
  const std::vector<double> q = robot.positions();
  for (std::size_t j = 1; j <= 2; ++j)  // shoulder lift and elbow: the joints that carry the weight
    out.error = std::max(out.error, std::abs(q[std::size_t(robot.jointIndex(spec.arm_joints[j]))] - stretched[j]));
  for (std::size_t j = 0; j < 6; ++j)
    if (const double e = std::abs(q[std::size_t(robot.jointIndex(spec.arm_joints[j]))] - stretched[j]); e > out.worst)
      out.worst = e, out.worst_joint = spec.arm_joints[j];
  out.held = world.heldObjects(spec.name);
  return out;
}
}  // namespace

TEST(Grasping, AHeldDrillDoesNotChangeWhereTheArmEnds)
{
  WorldOptions options;
  // sweeps enough for the squeezed grasp's rows to converge well below the load's own 1e-4 rad (at the
  // defaults, 30 and 5, the elbow stays 2e-4 rad off under this grip: SqueezingTheDrillLeavesTheArmWhereItWasSent)
  options.solver_iterations = 100;
  options.solver_inner_iterations = 20;
  const HeldLoad with = holdDrillStretched(options);
  options.payload_compensation = false;
  const HeldLoad without = holdDrillStretched(options);
  std::cout << "drill (1.5 kg) held stretched out: final error of shoulder lift and elbow " << with.error
            << " rad with payload compensation, " << without.error << " rad without\n";
  ASSERT_EQ(with.held, std::vector<std::string>{ "drill" });
  EXPECT_LT(with.error, 5e-5);          // measured 2.4e-5
  EXPECT_GT(without.error, 7e-5);       // measured 9.2e-5: m g r / K = 1.5 x 9.81 x 0.7 / 1e5 = 1.0e-4
  EXPECT_GT(without.error, 2.5 * with.error);
}

TEST(Grasping, SqueezingTheDrillLeavesTheArmWhereItWasSent)
{
  // Issue 22's abort (wrist_1 0.0117 rad off, goal tolerance 0.01): with Bullet's order of joint rows and contacts
  // the squeeze moved the wrists 3.6 mrad (70 N) and 13 mrad (235 N) at the default solver settings
  // (JointRowSolver's class comment).
  const HeldLoad demo = holdDrillStretched(WorldOptions(), 70.0), rated = holdDrillStretched(WorldOptions(), 235.0);
  std::cout << "drill squeezed and held stretched out at the default 30 / 5 solver sweeps: worst joint "
            << demo.worst_joint << " " << demo.worst << " rad with a 70 N grip, " << rated.worst_joint << " "
            << rated.worst << " rad with the rated 235 N\n";
  ASSERT_EQ(demo.held, std::vector<std::string>{ "drill" });
  ASSERT_EQ(rated.held, std::vector<std::string>{ "drill" });
  EXPECT_LT(demo.worst, 1.5e-3);  // measured 6.6e-4 (wrist_2); 3.6e-3 in Bullet's order
  EXPECT_LT(rated.worst, 8e-3);   // measured 4.2e-3 (wrist_2); 13e-3 in Bullet's order
}
