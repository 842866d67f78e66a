// Every suite scene (frame 0) rendered on two backends, with its reference:
// the loop of the tests that compare two backends, or two variants of one.
// The reference is the one at the minimum bits (4), the loosest a conformant
// device gets, from the build's reference cache ($LIGHTCTS_CACHE_DIR), which
// the scenes' own tests fill: computed once per scene, not once per test.
#pragma once

#include "backends/backend.h"
#include "baking/bake.h"
#include "conformance/reference_cache.h"
#include "conformance/scene_check.h"
#include "lighting/frame.h"
#include "lighting/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace backends::testing {

struct SceneRenders {
  std::filesystem::path file;
  imaging::Image first;
  imaging::Image second;
  reference::ReferenceImages reference;
};

// Calls `check` once per scene file under `scenesDir`, in name order, and
// returns how many there were.
inline int forEachSuiteScene(const std::filesystem::path& scenesDir, Backend& first, Backend& second,
                             const std::function<void(const SceneRenders&)>& check) {
  std::vector<std::filesystem::path> files;
  for (const auto& group : std::filesystem::directory_iterator(scenesDir))
    for (const auto& file : std::filesystem::directory_iterator(group.path()))
      if (file.path().extension() == ".json") files.push_back(file.path());
  std::sort(files.begin(), files.end());
  for (const std::filesystem::path& file : files) {
    lighting::Scene scene = lighting::loadSceneFile(file.string());
    const auto caching = conformance::referenceCaching(conformance::defaultReferenceCacheDirectory(), file, scene);
    conformance::SceneReferences references(baking::prepareBakedScene(std::move(scene)), caching);
    const lighting::Frame& frame = references.frame(0);
    check({file, first.render(frame), second.render(frame), references.reference(0)});
  }
  return int(files.size());
}

// SPEC 10's name of a scene file's test on a combination: <group>.<name>.<suffix>.
inline std::string sceneTestName(const std::filesystem::path& file, const std::string& suffix) {
  return file.parent_path().filename().string() + "." + file.stem().string() + "." + suffix;
}

// The tests the expected-failures files of `folder` (suite/expected-failures/,
// one file per driver, each naming its own combinations' tests) list: the
// drivers' known mismatches, which a test comparing two backends must not
// count against them either. Only the names; the format is runner/expected_failures.h's.
inline std::set<std::string> expectedFailingTests(const std::filesystem::path& folder) {
  std::set<std::string> tests;
  for (const std::filesystem::directory_entry& file : std::filesystem::directory_iterator(folder)) {
    if (file.path().extension() != ".txt") continue;
    std::ifstream in(file.path());
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      const std::size_t comma = line.find(',');
      if (comma != std::string::npos) tests.insert(line.substr(0, comma));
    }
  }
  return tests;
}

}  // namespace backends::testing
