#pragma once
#include <string>
#include <vector>

#include "vrrw_scene/scene.h"

namespace vrrw_scene
{
/// \brief Where the loader finds shipped descriptions and keeps expanded scenes.
struct LoadOptions
{
  std::string root;       ///< repository root holding urdf/; empty: $VRRW_ROOT or the build-time root
  std::string cache_dir;  ///< empty: $VRRW_CACHE_DIR, else $XDG_CACHE_HOME/vrrw, else ~/.cache/vrrw
  bool use_cache = true;  ///< false: always run xacro (the cache is still refreshed)
};

/// \brief Loads a scene by shipped name (urdf/scenes/NAME.yaml) or YAML path.
///
/// Robots and objects are expanded from their xacro macros into one URDF; the xacro output is
/// cached under a key made of the content of every input, so an unchanged scene skips xacro.
/// Throws SceneError with a one-line "file:line: field: reason" message.
Scene loadScene(const std::string& name_or_path, const LoadOptions& options = {});

/// \brief The scene YAML a name or path stands for; throws SceneError when there is none.
std::string resolveScenePath(const std::string& name_or_path, const LoadOptions& options = {});

/// \brief Names of the scenes shipped in urdf/scenes/.
std::vector<std::string> shippedScenes(const LoadOptions& options = {});

/// \brief The repository root in effect for these options.
std::string vrrwRoot(const LoadOptions& options = {});
}  // namespace vrrw_scene
