#pragma once
#include <string>

#include <vrrw_dmp/dmp.h>

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

/// \brief Writes the model file, complete or not at all (vrrw_trajectory::writeWholeFile); throws
/// DmpError naming the path.
void saveDmp(const Dmp& dmp, const std::string& path);
/// \brief Reads a model file; throws DmpError naming the path and the field.
Dmp loadDmp(const std::string& path);
}  // namespace vrrw_dmp
