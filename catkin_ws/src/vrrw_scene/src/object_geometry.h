#pragma once
#include <urdf_model/model.h>

#include "scene_spec.h"
#include "vrrw_scene/scene.h"

namespace vrrw_scene
{
/// \brief An object built from its expanded xacro macro: the link tree under the joint that
/// fixes it to world, shapes and inertia gathered into its root link's frame.
Object objectFromUrdf(const urdf::ModelInterface& model, const ObjectSpec& spec, bool fixed_by_kind);

/// \brief A box, cylinder, sphere or mesh object from the scene's own fields.
Object primitiveObject(const ObjectSpec& spec);
}  // namespace vrrw_scene
