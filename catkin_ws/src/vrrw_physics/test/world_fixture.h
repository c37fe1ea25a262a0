#pragma once
// Shared by the PhysicsWorld tests: shipped scenes, the one-line InputError of a call, a step loop.
#include <vrrw_physics/physics_world.h>
#include <vrrw_scene/scene_loader.h>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace vrrw_physics_test
{
inline vrrw_scene::Scene shippedScene(const std::string& name)
{
  vrrw_scene::LoadOptions options;
  options.root = VRRW_TEST_ROOT;
  return vrrw_scene::loadScene(name, options);
}

/// The message of the InputError `call` throws (a test failure when it throws none or a second line).
inline std::string inputErrorOf(const std::function<void()>& call)
{
  try
  {
    call();
  }
  catch (const vrrw_physics::InputError& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

/// Steps `seconds` of simulated time, each step before it running `each` (may be empty); fails the test at a
/// guard trip.
inline void run(vrrw_physics::PhysicsWorld& world, double seconds, const std::function<void()>& each = {})
{
  const long steps = std::lround(seconds / world.options().dt);
  for (long i = 0; i < steps; ++i)
  {
    if (each)
      each();
    ASSERT_TRUE(world.step()) << world.lastError();
  }
}

inline double largestJointSpeed(const vrrw_physics::PhysicsWorld& world, const std::string& robot)
{
  double speed = 0.0;
  for (double v : world.jointStates(robot).velocity)
    speed = std::max(speed, std::abs(v));
  return speed;
}
}  // namespace vrrw_physics_test
