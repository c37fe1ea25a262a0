#pragma once
#include <string>

#include <vrrw_demos/demonstration.h>
#include <vrrw_demos/segmentation.h>

#include <vrrw_demos/ros/demo_bag.h>

namespace vrrw_demos
{
/// \brief Segments every robot of a demonstration and renders YAML (with TCP poses at the boundaries,
/// by forward kinematics of the bag's URDF when it has one) and a table for the terminal.
struct SegmentReport
{
  std::string yaml;
  std::string table;
};

SegmentReport segmentReport(const std::string& bag, const Demonstration& demo,
                            const SegmentationOptions& options);
}  // namespace vrrw_demos
