#pragma once
#include <string>

namespace vrrw_trajectory
{
/// \brief Writes \a contents to \a path so that the file appears complete or not at all: the text goes
/// to a temporary file beside it (same folder, so the rename cannot cross file systems), is flushed to
/// disk, and is renamed over \a path only then. On any failure the temporary file is removed, an
/// existing \a path is left as it was, and a TrajectoryError "PATH: reason" is thrown.
void writeWholeFile(const std::string& path, const std::string& contents);
}  // namespace vrrw_trajectory
