#include "conformance/scene_catalogue.h"

#include <algorithm>
#include <stdexcept>

namespace conformance {
namespace {

namespace fs = std::filesystem;

void addScenesOf(const fs::path& folder, std::vector<SceneFile>& scenes) {
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      scenes.push_back({folder.filename().string(), entry.path().stem().string(), entry.path()});
}

}  // namespace

std::vector<SceneFile> findSceneFiles(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw std::runtime_error("scene folder " + dir.string() + " is not a folder");
  // lexically_normal drops a trailing '/', so a group folder keeps its name.
  const fs::path folder = fs::path(dir).lexically_normal();
  const fs::path named = folder.filename().empty() ? folder.parent_path() : folder;
  std::vector<SceneFile> scenes;
  addScenesOf(named, scenes);
  if (scenes.empty())
    for (const fs::directory_entry& entry : fs::directory_iterator(named))
      if (entry.is_directory()) addScenesOf(entry.path(), scenes);
  if (scenes.empty()) throw std::runtime_error("scene folder " + dir.string() + " holds no <group>/<name>.json file");
  std::sort(scenes.begin(), scenes.end(), [](const SceneFile& a, const SceneFile& b) {
    return a.group != b.group ? a.group < b.group : a.name < b.name;
  });
  return scenes;
}

}  // namespace conformance
