// The loop of the tests that hold a backend, or a variant of one, to every
// suite scene's own comparison (the scene files and their test names are
// conformance/scene_catalogue.h's): each scene's
// references from the build's reference cache ($LIGHTCTS_CACHE_DIR, which
// the scenes' own tests fill: computed once per scene, not once per test),
// SPEC 10's test names and the drivers' known mismatches.
#pragma once

#include "baking/bake.h"
#include "conformance/reference_cache.h"
#include "conformance/scene_catalogue.h"
#include "conformance/scene_check.h"
#include "runner/expected_failures.h"
#include "scene_input/scene_loader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace backends::testing {

// The scene's references, read from and left in the build's reference cache.
inline conformance::SceneReferences cachedSceneReferences(const std::filesystem::path& file, lighting::Scene scene) {
  const auto caching = conformance::referenceCaching(conformance::defaultReferenceCacheDirectory(), file, scene);
  return conformance::SceneReferences(baking::prepareBakedScene(std::move(scene)), caching);
}

// The expected-failures files of `folder` (suite/expected-failures/, one
// file per driver, each naming its own combinations' tests), read by the
// runner's reader: the drivers' known mismatches, which a test of a variant
// must not count against them either.
inline runner::ExpectedFailures suiteExpectedFailures(const std::filesystem::path& folder) {
  runner::ExpectedFailures expected;
  for (const std::filesystem::directory_entry& file : std::filesystem::directory_iterator(folder))
    if (file.path().extension() == ".txt") expected.load(file.path());
  return expected;
}

}  // namespace backends::testing
