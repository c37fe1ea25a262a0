#include "urdf_physics_check.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <sstream>

#include "physical_ranges.h"
#include "vrrw_scene/scene.h"

using tinyxml2::XMLElement;

namespace vrrw_scene
{
namespace
{
std::string nameOf(const XMLElement& element)
{
  const char* name = element.Attribute("name");
  return name ? name : "";
}

[[noreturn]] void fail(const std::string& source, const XMLElement& at, const std::string& owner,
                       const std::string& field, const std::string& reason)
{
  throw SceneError(source + ":" + std::to_string(at.GetLineNum()) + ": " + owner + ": " + field + ": " + reason);
}

/// The attribute as a finite number; `fallback` when absent.
double number(const XMLElement& element, const char* attribute, double fallback, const std::string& source,
              const std::string& owner, const std::string& field)
{
  const char* text = element.Attribute(attribute);
  if (!text)
    return fallback;
  std::istringstream in(text);
  double value;
  if (!(in >> value) || !(in >> std::ws).eof() || !std::isfinite(value))
    fail(source, element, owner, field, "expected a finite number, got '" + std::string(text) + "'");
  return value;
}

std::string str(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string outside(double value, double lo, double hi, const std::string& unit)
{
  return str(value) + " outside [" + str(lo) + ", " + str(hi) + "] " + unit + " (beyond any workspace cell)";
}
}  // namespace

void checkJointMotion(const XMLElement& joint, const std::string& source)
{
  const char* type_attribute = joint.Attribute("type");
  const std::string type = type_attribute ? type_attribute : "";
  if (type == "fixed" || type == "floating")
    return;
  const std::string owner = "joint '" + nameOf(joint) + "'";
  if (const XMLElement* axis = joint.FirstChildElement("axis"))
  {
    std::istringstream in(axis->Attribute("xyz") ? axis->Attribute("xyz") : "1 0 0");
    Eigen::Vector3d xyz;
    if (!(in >> xyz.x() >> xyz.y() >> xyz.z()) || !xyz.allFinite())
      fail(source, *axis, owner, "axis xyz", "expected three finite numbers");
    if (xyz.norm() < 1e-9)  // a joint that moves along no direction: KDL and Bullet divide by this norm
      fail(source, *axis, owner, "axis xyz", "the axis is zero; give the direction the joint moves along");
  }
  const XMLElement* limit = joint.FirstChildElement("limit");
  if (!limit)
    return;
  const double lower = number(*limit, "lower", 0.0, source, owner, "limit lower");
  const double upper = number(*limit, "upper", 0.0, source, owner, "limit upper");
  if (type != "continuous" && lower > upper)
    fail(source, *limit, owner, "limit lower", str(lower) + " is above the upper limit " + str(upper));
  for (const auto& [field, value] : { std::pair{ "limit lower", lower }, std::pair{ "limit upper", upper } })
    if (type != "continuous" && std::abs(value) > ranges::kMaxJointTravel)
      fail(source, *limit, owner, field, outside(value, -ranges::kMaxJointTravel, ranges::kMaxJointTravel, "rad or m"));
  if (limit->Attribute("effort"))
  {
    const double effort = number(*limit, "effort", 0.0, source, owner, "limit effort");
    if (effort < 0.0 || effort > ranges::kMaxEffort)  // the drives' force limit: negative is no force at all
      fail(source, *limit, owner, "limit effort", outside(effort, 0.0, ranges::kMaxEffort, "N m or N"));
  }
  if (limit->Attribute("velocity"))
  {
    const double velocity = number(*limit, "velocity", 0.0, source, owner, "limit velocity");
    if (velocity <= 0.0)  // time parameterization divides by it; the controller could never move the joint
      fail(source, *limit, owner, "limit velocity", "must be greater than zero, got " + str(velocity));
    if (velocity > ranges::kMaxVelocity)
      fail(source, *limit, owner, "limit velocity", outside(velocity, 0.0, ranges::kMaxVelocity, "rad/s or m/s"));
  }
}

void checkLinkInertia(const XMLElement& link, const std::string& source)
{
  const XMLElement* inertial = link.FirstChildElement("inertial");
  if (!inertial)
    return;
  const std::string owner = "link '" + nameOf(link) + "'";
  if (const XMLElement* mass = inertial->FirstChildElement("mass"))
  {
    const double value = number(*mass, "value", 0.0, source, owner, "inertial mass");
    if (value <= 0.0)
      fail(source, *mass, owner, "inertial mass", "must be greater than zero, got " + str(value));
    if (value > ranges::kMaxMass)
      fail(source, *mass, owner, "inertial mass", outside(value, 0.0, ranges::kMaxMass, "kg"));
  }
  const XMLElement* inertia = inertial->FirstChildElement("inertia");
  if (!inertia)
    return;
  Eigen::Matrix3d tensor;
  const char* names[3][3] = { { "ixx", "ixy", "ixz" }, { "ixy", "iyy", "iyz" }, { "ixz", "iyz", "izz" } };
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      tensor(r, c) = number(*inertia, names[r][c], 0.0, source, owner, std::string("inertial inertia ") + names[r][c]);
  for (int i = 0; i < 3; ++i)
    if (tensor(i, i) < 0.0)
      fail(source, *inertia, owner, std::string("inertial inertia ") + names[i][i],
           "must not be negative, got " + str(tensor(i, i)));
  const Eigen::Vector3d principal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor).eigenvalues();
  const double slack = 1e-9 * std::max(1e-12, principal.cwiseAbs().sum());  // rounding of printed values
  if (principal.minCoeff() < -slack)
    fail(source, *inertia, owner, "inertial inertia",
         "not positive semi-definite (principal moment " + str(principal.minCoeff()) + ")");
  const double largest = principal.maxCoeff();
  if (largest > ranges::kMaxInertia)
    fail(source, *inertia, owner, "inertial inertia",
         "principal moment " + outside(largest, 0.0, ranges::kMaxInertia, "kg m^2"));
  if (largest > principal.sum() - largest + slack)
    fail(source, *inertia, owner, "inertial inertia",
         "principal moments " + str(principal[0]) + ", " + str(principal[1]) + ", " + str(principal[2]) +
             " break the triangle inequality (" + str(largest) + " > " + str(principal.sum() - largest) +
             "); no rigid body has them");
}
}  // namespace vrrw_scene
