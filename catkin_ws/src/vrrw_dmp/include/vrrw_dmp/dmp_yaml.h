#pragma once
#include <string>
#include <vector>

#include <vrrw_dmp/cartesian_dmp.h>
#include <vrrw_dmp/dmp.h>

namespace YAML
{
class Emitter;
class Node;
}  // namespace YAML

namespace vrrw_dmp
{
/// Model files are YAML (format "vrrw_dmp/1"): parameters (N, alpha, K, D, scaling), the basis
/// (centres, widths), per joint its name, weights, scaling, demonstrated start/goal/range, the demo
/// duration (= its tau), learning warnings and provenance (source, created, samples, checksum).
/// Doubles are written with 17 significant digits, so a saved and loaded model rolls out identically.

/// \brief The model as YAML text.
std::string toYaml(const Dmp& dmp);
/// \brief Parses YAML text; \a source names it in errors. Throws DmpError.
Dmp fromYaml(const std::string& text, const std::string& source);

/// \brief A model's fields (the mapping toYaml writes, without `format`) into a mapping the caller opened
/// on \a out: how a file of another kind (a skill) carries a model.
void emitDmpFields(YAML::Emitter& out, const Dmp& dmp);
/// \brief A model from such a mapping; errors name \a source and the field below \a path (e.g.
/// "instructions[1].joint_dmp."). Throws DmpError.
Dmp parseDmpFields(const YAML::Node& node, const std::string& source, const std::string& path);

/// \brief A Cartesian model's fields: `position` (emitDmpFields of the x, y, z model) and `orientation`
/// (per axis its scaling and weights, the demonstrated start, goal and range as quaternions x, y, z, w and
/// rotation vectors, warnings; parameters, basis and duration are the position's).
void emitCartesianDmpFields(YAML::Emitter& out, const CartesianDmp& dmp);
/// \brief The Cartesian model from such a mapping. Throws DmpError naming the field (a quaternion whose
/// norm is not 1 among them).
CartesianDmp parseCartesianDmpFields(const YAML::Node& node, const std::string& source, const std::string& path);

/// \brief \a text as a YAML mapping: the one way model and skill files are opened. Throws DmpError
/// "SOURCE:LINE: not YAML (cut short?): reason" for text yaml-cpp cannot parse, "SOURCE: WHAT: expected a YAML
/// mapping (an empty or cut-short file?)" for any other document (\a what: "model", "skill").
YAML::Node loadYamlMapping(const std::string& text, const std::string& source, const std::string& what);
/// \brief \a values as one flow list ([a, b, c]) on \a out.
void emitNumbers(YAML::Emitter& out, const std::vector<double>& values);

/// \brief Writes the model file, complete or not at all (vrrw_trajectory::writeWholeFile); throws
/// DmpError naming the path.
void saveDmp(const Dmp& dmp, const std::string& path);
/// \brief Reads a model file; throws DmpError naming the path and the field.
Dmp loadDmp(const std::string& path);
}  // namespace vrrw_dmp
