#pragma once
#include <cstddef>
#include <string>
#include <vrrw_scene/scene.h>

namespace vrrw_interaction
{
/// \brief A colour, 0..1 each.
struct Tint
{
  double r = 0.0, g = 0.0, b = 0.0;
};

/// \brief The ghost colour of a scene's `index`-th robot: hues far from the robots' own greys, blues and blacks
/// (orange, teal, magenta, lime, then again), so a ghost reads as a ghost next to its robot and beside another.
Tint ghostTint(std::size_t index);

/// \brief The scene's URDF with every visual of each robot's links (named `<robot>_...`) in that robot's
/// ghostTint: the description rviz draws the ghosts from (parameter /ghost_description). Throws
/// InteractionError when scene.urdf is not XML.
std::string ghostDescription(const vrrw_scene::Scene& scene);
}  // namespace vrrw_interaction
