#pragma once
#include <tinyxml2.h>

#include <string>

namespace vrrw_scene
{
/// \brief Rejects a movable joint that nothing downstream can use: lower limit above upper, a velocity
/// limit of zero or less, a zero axis, a number that is not one. Throws SceneError
/// "source:line: joint 'name': field: reason", the line being the offending element's.
void checkJointMotion(const tinyxml2::XMLElement& joint, const std::string& source);

/// \brief Rejects an inertial no rigid body has: mass of zero or less, a negative diagonal entry, principal
/// moments that break the triangle inequality. Throws SceneError "source:line: link 'name': field: reason".
void checkLinkInertia(const tinyxml2::XMLElement& link, const std::string& source);
}  // namespace vrrw_scene
