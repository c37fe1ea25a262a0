#pragma once
#include <string>

namespace vrrw_demos
{
/// \brief Suffix of a bag while the recorder writes it (renamed to the bag's name when it closes).
constexpr const char* kActiveSuffix = ".active";

/// \brief Throws DemoError when \a path may not be written by a new writer: it exists, or a recording is
/// being written to `path.active` (or was killed there: recover it first). Every writer of vrrw_demos
/// (recorder, import, export, segment, plot) asks this first, so none takes another's file.
void refuseTaken(const std::string& path);

/// \brief A new, empty, exclusively created file beside \a path (same folder, so it can be linked there),
/// named after it; its name. Throws DemoError when the folder is not writable.
std::string temporaryBeside(const std::string& path);

/// \brief Makes the complete file \a temporary appear at \a path, never over an existing file (a link,
/// which fails when the name is taken), and removes \a temporary. Throws DemoError (temporary removed).
void publishNewFile(const std::string& temporary, const std::string& path);

/// \brief Writes \a contents to the new file \a path: complete or not at all, never over anything.
void writeNewFile(const std::string& path, const std::string& contents);
}  // namespace vrrw_demos
