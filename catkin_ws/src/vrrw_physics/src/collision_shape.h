#pragma once
#include <memory>

#include <vrrw_scene/scene.h>

class btCollisionShape;

namespace vrrw_physics
{
/// \brief The Bullet shape of a scene shape (box, cylinder along z, sphere, convex hull of an STL/OBJ
/// mesh), in its own frame (the caller places it by shape.origin), with a 1 mm collision margin.
/// Throws std::runtime_error "mesh PATH: reason" for a mesh that cannot be read.
std::unique_ptr<btCollisionShape> makeCollisionShape(const vrrw_scene::Shape& shape);
}  // namespace vrrw_physics
