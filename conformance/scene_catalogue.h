// The scene files of a suite folder (SPEC 10): suite/scenes/<group>/<name>.json.
// A folder that holds .json files itself is one group, named after the folder.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace conformance {

struct SceneFile {
  std::string group;
  std::string name;  // the file's stem
  std::filesystem::path path;
  // <group>.<name>: the test name without its backend (SPEC 10).
  std::string caseName() const { return group + "." + name; }
};

// Sorted by group, then name. Throws std::runtime_error when `dir` is not a
// folder or holds no scene.
std::vector<SceneFile> findSceneFiles(const std::filesystem::path& dir);

}  // namespace conformance
