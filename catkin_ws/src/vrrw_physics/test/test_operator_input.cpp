// OperatorInput through PhysicsWorld: springs and hands refuse what they cannot carry, an operator spring
// drags a compliant wrist, hands glide between tracker updates and go when their tracker falls silent.
#include <vrrw_physics/physics_world.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "world_fixture.h"

using namespace vrrw_physics;
using vrrw_physics_test::inputErrorOf;
using vrrw_physics_test::run;
using vrrw_physics_test::shippedScene;

namespace
{
Eigen::Isometry3d at(const Eigen::Vector3d& p)
{
  return Eigen::Isometry3d(Eigen::Translation3d(p));
}

struct Drag
{
  double rms = 0.0;       ///< m: grabbed point from the target while the target moves
  double largest = 0.0;   ///< m
  double end_error = 0.0; ///< m, 0.5 s after the target stopped
  int rejected = 0;
};

/// The UR5e of pick_place_drill compliant (K = 0, D = 30); a spring with these gains grabs the centre of the
/// wrist_3 link (the flange) and its target moves 20 cm along `direction` at 0.2 m/s.
Drag dragWrist(double stiffness, double damping, const Eigen::Vector3d& direction)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  world.setMode("ur5e", DriveMode::Compliant);
  const std::string link = "ur5e_wrist_3_link";
  const Eigen::Vector3d start = world.framePose(link).translation();
  OperatorSpring spring;
  spring.body = link;
  spring.stiffness = stiffness;
  spring.damping = damping;
  spring.max_force = kMaxSpringForce;
  spring.target = at(start);
  world.operatorInput().attachSpring("grab", spring);
  Drag drag;
  double sum = 0.0;
  int samples = 0;
  const double speed = 0.2, length = 0.2;
  for (int i = 0; i < 1500; ++i)
  {
    const double t = std::min(world.time(), length / speed);
    const Eigen::Vector3d target = start + speed * t * direction;
    const bool moving = world.time() < length / speed;
    const Eigen::Vector3d velocity = moving ? Eigen::Vector3d(speed * direction) : Eigen::Vector3d::Zero();
    world.operatorInput().moveSpring("grab", at(target), velocity);
    drag.rejected += !world.step();
    const Eigen::Vector3d now = start + speed * std::min(world.time(), length / speed) * direction;
    const double error = (world.framePose(link).translation() - now).norm();
    if (moving)
    {
      sum += error * error;
      ++samples;
      drag.largest = std::max(drag.largest, error);
    }
    drag.end_error = error;
  }
  drag.rms = std::sqrt(sum / samples);
  return drag;
}
}  // namespace

TEST(OperatorInput, SpringsAndHandsRefuseWhatTheyCannotCarry)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  OperatorInput& input = world.operatorInput();
  const auto mentions = [](const std::string& error, const std::string& text) {
    EXPECT_NE(error.find(text), std::string::npos) << error;
  };
  OperatorSpring spring;
  spring.body = "ur5e_wrist_3_link";
  spring.target = world.framePose("ur5e_wrist_3_link");
  OperatorSpring wild = spring;  // the probe that froze the node: stiffness and max_force 1e12
  wild.stiffness = 1e12;
  mentions(inputErrorOf([&] { input.attachSpring("s", wild); }), "stiffness: 1e+12 outside [0, 10000] N/m");
  wild = spring;
  wild.max_force = 1e12;
  mentions(inputErrorOf([&] { input.attachSpring("s", wild); }), "max_force: 1e+12 outside [1e-06, 1000] N");
  wild = spring;
  wild.target.translation().x() = 1e300;
  mentions(inputErrorOf([&] { input.attachSpring("s", wild); }), "target: position.x: 1e+300 outside [-100, 100] m");
  wild = spring;
  wild.point = Eigen::Vector3d(0, 0, 5.0);
  mentions(inputErrorOf([&] { input.attachSpring("s", wild); }), "point (distance from the body's frame): 5 outside");
  wild = spring;
  wild.body = "table";
  mentions(inputErrorOf([&] { input.attachSpring("s", wild); }), "object 'table' is fixed");
  mentions(inputErrorOf([&] { input.attachSpring("", spring); }), "the id is empty");
  mentions(inputErrorOf([&] { input.moveSpring("s", spring.target); }), "spring 's': not attached");
  input.attachSpring("s", spring);
  mentions(inputErrorOf([&] { input.moveSpring("s", spring.target, Eigen::Vector3d(0, 0, 1e3)); }),
           "target velocity: 1000 outside [0, 10] m/s");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  mentions(inputErrorOf([&] { input.setHand("left", at(Eigen::Vector3d(nan, 0, 0)), 0.05); }), "not finite");
  mentions(inputErrorOf([&] { input.setHand("left", at(Eigen::Vector3d::Zero()), 1.0); }),
           "radius: 1 outside [0, 0.25] m");
  EXPECT_EQ(input.springs(), std::vector<std::string>{ "s" });
  EXPECT_TRUE(input.hands().empty());
  run(world, 0.1);
}

TEST(OperatorInput, SpringDragsTheCompliantWristAlongALineWithinTwoCentimetres)
{
  // The issue-11 figure with the recommended gains (OperatorSpring's defaults), along and against each axis.
  const OperatorSpring recommended;
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  for (const Eigen::Vector3d& direction : { y, Eigen::Vector3d(-y), z, Eigen::Vector3d(-z), x, Eigen::Vector3d(-x) })
  {
    const Drag drag = dragWrist(recommended.stiffness, recommended.damping, direction);
    std::cout << "drag along (" << direction.transpose() << "): rms " << drag.rms << " m, largest " << drag.largest
              << " m, 0.5 s after the stop " << drag.end_error << " m, guard trips " << drag.rejected << "\n";
    EXPECT_LT(drag.rms, 0.02);
    EXPECT_LT(drag.end_error, 2e-3);
    EXPECT_EQ(drag.rejected, 0);
  }
}

TEST(OperatorInput, SeveralHandsAndASilentOneIsRemoved)
{
  PhysicsWorld world(shippedScene("pick_place_drill"));
  OperatorInput& input = world.operatorInput();
  const Eigen::Vector3d above = world.objectPose("drill").translation() + Eigen::Vector3d(0, 0, 0.5);
  input.setHand("left", at(above), 0.05);
  input.setHand("right", at(above + Eigen::Vector3d(0.2, 0, 0)), 0.05);
  input.setHand("third", at(above + Eigen::Vector3d(0.4, 0, 0)), 0.05);
  EXPECT_EQ(input.hands(), (std::vector<std::string>{ "left", "right", "third" }));
  input.setHand("third", at(above), 0.0);  // radius 0 removes a hand
  EXPECT_EQ(input.hands(), (std::vector<std::string>{ "left", "right" }));
  run(world, 0.45, [&] { input.setHand("right", at(above + Eigen::Vector3d(0.2, 0, 0)), 0.05); });
  EXPECT_EQ(input.hands().size(), 2u);
  run(world, 0.1, [&] { input.setHand("right", at(above + Eigen::Vector3d(0.2, 0, 0)), 0.05); });
  EXPECT_EQ(input.hands(), std::vector<std::string>{ "right" });  // "left" was silent for 0.5 s
  const std::vector<std::string> reports = world.takeReports();
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_NE(reports[0].find("hand 'left': no pose for 0.5"), std::string::npos) << reports[0];
}

TEST(OperatorInput, AHandTrackedAt50HzGlidesAndPushesTheDrillWithoutKicks)
{
  // A tracker at 50 Hz sweeps a 4 cm sphere along +y through the drill's battery at 0.3 m/s: 6 mm per update,
  // which a sphere jumping in one 1 ms step would hit at 6 m/s.
  PhysicsWorld world(shippedScene("pick_place_drill"));
  const Eigen::Vector3d drill = world.objectPose("drill").translation();
  const Eigen::Vector3d from = drill + Eigen::Vector3d(0, -0.15, 0.03);
  double fastest = 0.0;
  for (int i = 0; i <= 1000; ++i)
  {
    if (i % 20 == 0)
      world.operatorInput().setHand("right", at(from + Eigen::Vector3d(0, 0.3 * world.time(), 0)), 0.04);
    ASSERT_TRUE(world.step()) << world.lastError();
    fastest = std::max(fastest, world.snapshot().object_linear[1].norm());
  }
  const double pushed = world.objectPose("drill").translation().y() - drill.y();
  std::cout << "hand at 50 Hz: swept 0.3 m, the drill moved " << pushed << " m, at most " << fastest << " m/s\n";
  EXPECT_GT(pushed, 0.05);
  EXPECT_LT(fastest, 1.0);
}
