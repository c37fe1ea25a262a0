#pragma once

namespace vrrw_demos
{
/// \brief `replay BAG --mode fake|physics|real ...` on the running workspace; returns the exit code.
int runReplay(int argc, char** argv);
}  // namespace vrrw_demos
