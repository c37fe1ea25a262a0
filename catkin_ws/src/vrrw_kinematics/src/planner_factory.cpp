#include "vrrw_kinematics/planner_factory.h"

#include <functional>
#include <map>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/est/ProjEST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/prm/SPARS.h>
#include <ompl/geometric/planners/prm/SPARStwo.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTXstatic.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/SORRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/sst/SST.h>
#include <ompl/geometric/planners/stride/STRIDE.h>

namespace vrrw_kinematics
{
namespace
{
using Allocator = std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr&)>;

template <typename T>
Allocator allocator()
{
  return [](const ompl::base::SpaceInformationPtr& si) { return std::make_shared<T>(si); };
}

const std::map<std::string, Allocator>& planners()
{
  namespace og = ompl::geometric;
  static const std::map<std::string, Allocator> table = {
    { "RRTConnect", allocator<og::RRTConnect>() },   { "RRT", allocator<og::RRT>() },
    { "RRTstar", allocator<og::RRTstar>() },         { "BiTRRT", allocator<og::BiTRRT>() },
    { "LBTRRT", allocator<og::LBTRRT>() },           { "TRRT", allocator<og::TRRT>() },
    { "LazyRRT", allocator<og::LazyRRT>() },         { "InformedRRTstar", allocator<og::InformedRRTstar>() },
    { "RRTsharp", allocator<og::RRTsharp>() },       { "RRTXstatic", allocator<og::RRTXstatic>() },
    { "SORRTstar", allocator<og::SORRTstar>() },     { "PRM", allocator<og::PRM>() },
    { "PRMstar", allocator<og::PRMstar>() },         { "LazyPRM", allocator<og::LazyPRM>() },
    { "LazyPRMstar", allocator<og::LazyPRMstar>() }, { "SPARS", allocator<og::SPARS>() },
    { "SPARStwo", allocator<og::SPARStwo>() },       { "KPIECE1", allocator<og::KPIECE1>() },
    { "BKPIECE1", allocator<og::BKPIECE1>() },       { "LBKPIECE1", allocator<og::LBKPIECE1>() },
    { "EST", allocator<og::EST>() },                 { "BiEST", allocator<og::BiEST>() },
    { "ProjEST", allocator<og::ProjEST>() },         { "SBL", allocator<og::SBL>() },
    { "STRIDE", allocator<og::STRIDE>() },           { "PDST", allocator<og::PDST>() },
    { "FMT", allocator<og::FMT>() },                 { "BFMT", allocator<og::BFMT>() },
    { "BITstar", allocator<og::BITstar>() },         { "ABITstar", allocator<og::ABITstar>() },
    { "AITstar", allocator<og::AITstar>() },         { "SST", allocator<og::SST>() },
  };
  return table;
}
}  // namespace

ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si)
{
  const auto it = planners().find(name);
  return it == planners().end() ? nullptr : it->second(si);
}

std::vector<std::string> plannerNames()
{
  std::vector<std::string> names;
  for (const auto& entry : planners())
    names.push_back(entry.first);
  return names;
}
}  // namespace vrrw_kinematics
