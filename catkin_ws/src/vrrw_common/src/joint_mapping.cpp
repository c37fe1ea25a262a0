#include "vrrw_common/joint_mapping.h"

#include <algorithm>

namespace vrrw_common
{
namespace
{
/// Where a joint name is missing from the message.
constexpr std::size_t kMissing = static_cast<std::size_t>(-1);
/// Where a joint name is in the message twice.
constexpr std::size_t kTwice = static_cast<std::size_t>(-2);

/// Index of each wanted name in given, kMissing or kTwice. No allocation but the result: it runs per message.
std::vector<std::size_t> lookUp(const std::vector<std::string>& given, const std::vector<std::string>& wanted)
{
  std::vector<std::size_t> mapping;
  mapping.reserve(wanted.size());
  for (std::size_t i = 0; i < wanted.size(); ++i)
  {
    const auto& name = wanted[i];
    const auto found = std::find(given.begin(), given.end(), name);
    if (found == given.end())
      mapping.push_back(kMissing);
    else if (std::find(found + 1, given.end(), name) != given.end() ||
             std::find(wanted.begin(), wanted.begin() + static_cast<std::ptrdiff_t>(i), name) !=
                 wanted.begin() + static_cast<std::ptrdiff_t>(i))
      mapping.push_back(kTwice);
    else
      mapping.push_back(static_cast<std::size_t>(found - given.begin()));
  }
  return mapping;
}

JointMappingError twice(const std::string& joint)
{
  return JointMappingError("joint names: " + joint + " named twice", joint, "named twice");
}

JointMappingError notTheRobots(const std::string& joint)
{
  return JointMappingError("joint names: " + joint + " is not a joint of the robot", joint, "not a joint of the robot");
}
}  // namespace

std::vector<std::size_t> jointMapping(const std::vector<std::string>& given, const std::vector<std::string>& wanted,
                                      OtherJoints others)
{
  if (others == OtherJoints::Refuse)
    robotIndices(given, wanted);  // every name the robot's, none twice
  const auto mapping = lookUp(given, wanted);
  std::string missing, first_missing;
  for (std::size_t i = 0; i < wanted.size(); ++i)
  {
    if (mapping[i] == kTwice)
      throw twice(wanted[i]);
    if (mapping[i] == kMissing)
    {
      first_missing = missing.empty() ? wanted[i] : first_missing;
      missing += (missing.empty() ? "" : ", ") + wanted[i];
    }
  }
  if (!missing.empty())
    throw JointMappingError("joint names: missing " + missing, first_missing, "missing");
  return mapping;
}

std::vector<std::size_t> robotIndices(const std::vector<std::string>& given, const std::vector<std::string>& robot)
{
  std::vector<std::size_t> indices;
  indices.reserve(given.size());
  for (auto name = given.begin(); name != given.end(); ++name)
  {
    if (std::find(given.begin(), name, *name) != name)
      throw twice(*name);
    const auto found = std::find(robot.begin(), robot.end(), *name);
    if (found == robot.end())
      throw notTheRobots(*name);
    indices.push_back(static_cast<std::size_t>(found - robot.begin()));
  }
  return indices;
}

std::optional<std::vector<std::size_t>> findJoints(const std::vector<std::string>& given,
                                                    const std::vector<std::string>& wanted)
{
  auto mapping = lookUp(given, wanted);
  for (const std::size_t index : mapping)
    if (index == kMissing || index == kTwice)
      return std::nullopt;
  return mapping;
}

std::optional<std::vector<double>> findValues(const std::vector<std::string>& names, const std::vector<double>& values,
                                              const std::vector<std::string>& wanted)
{
  const auto mapping = findJoints(names, wanted);
  if (!mapping)
    return std::nullopt;
  std::vector<double> ordered;
  ordered.reserve(wanted.size());
  for (const std::size_t index : *mapping)
  {
    if (index >= values.size())
      return std::nullopt;
    ordered.push_back(values[index]);
  }
  return ordered;
}

std::vector<double> inRobotOrder(const std::vector<double>& values, const std::vector<std::size_t>& mapping,
                                 const std::string& field)
{
  std::vector<double> ordered;
  if (values.empty())
    return ordered;
  ordered.reserve(mapping.size());
  for (const std::size_t index : mapping)
  {
    if (index >= values.size())
      throw JointMappingError(field + ": " + std::to_string(values.size()) + " values, joint " +
                                  std::to_string(index + 1) + " of the names has none",
                              "", "no value");
    ordered.push_back(values[index]);
  }
  return ordered;
}
}  // namespace vrrw_common
