#pragma once
// What the library tests share: a shipped scene, its collision world and its initial state (no ROS).
#include <gtest/gtest.h>
#include <vrrw_kinematics/arm.h>
#include <vrrw_kinematics/scene_state.h>
#include <vrrw_scene/scene_loader.h>

namespace vrrw_interaction_test
{
struct Cell
{
  explicit Cell(const std::string& name)
    : scene(vrrw_scene::loadScene(name))
    , world(vrrw_kinematics::CollisionWorld::fromScene(scene))
    , state(vrrw_kinematics::initialState(world.model(), scene))
  {
    world.loadOrComputeAllowedCollisions(scene.cache_dir);
  }
  /// \brief World pose of a link at `at`.
  Eigen::Isometry3d link(const std::string& name, const Eigen::VectorXd& at) const
  {
    return world.model().relativeTransform(at, world.model().links()[0].name, name);
  }
  vrrw_scene::Scene scene;
  vrrw_kinematics::CollisionWorld world;
  Eigen::VectorXd state;
};
}  // namespace vrrw_interaction_test
