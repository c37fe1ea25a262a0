#pragma once
#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>
#include <string>
#include <vector>

namespace vrrw_kinematics
{
/// \brief An OMPL geometric planner by its class name ("RRTConnect", "PRMstar", ...); nullptr when unknown.
ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si);
/// \brief Names makePlanner knows.
std::vector<std::string> plannerNames();
}  // namespace vrrw_kinematics
