#pragma once
#include <atomic>

namespace vrrw_demos
{
/// \brief `replay BAG --mode fake|physics|real ...` on the running workspace; returns the exit code (0 done,
/// 1 the controller did not succeed). Throws DemoError for bad input (nothing was sent then) and
/// std::invalid_argument for bad usage. \a interrupted (a signal's flag) cancels the running goals.
int runReplay(int argc, char** argv, const std::atomic<bool>& interrupted);
}  // namespace vrrw_demos
