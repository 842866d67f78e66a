// --suite_scenes: frame 0 of every suite scene of the catalogue
// (conformance::findSceneFiles, SPEC 10), `frame` kind, named
// frame/<combination>/<group>.<name>/<mode>, with its error against its own
// ideal reference.
#include "baking/bake.h"
#include "conformance/scene_catalogue.h"
#include "scene_input/scene_loader.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

#include <cstdio>
#include <exception>
#include <vector>

namespace bench {

void registerSuiteScenes(Registrar& r) {
  const std::filesystem::path& root = r.run().settings.scenes;
  std::vector<conformance::SceneFile> files;
  try {
    files = conformance::findSceneFiles(root);
  } catch (const std::exception& e) {  // not a folder, or no scene in it: nothing to register
    std::fprintf(stderr, "render_bench: no suite scenes in %s (%s)\n", root.c_str(), e.what());
  }
  for (const conformance::SceneFile& file : files) {
    const std::string sceneId = file.caseName();
    try {
      // Loaded now for its mode (a benchmark's name); baked and traced when a
      // benchmark the filter keeps first needs it.
      auto scene = std::make_shared<lighting::Scene>(scene_input::loadSceneFile(file.path.string()));
      const std::string mode = modeName(frameModeOf(scene->pipeline));
      r.frame(sceneId, mode, "", lazyBenchFrame(true, [scene, sceneId] {
                BenchFrameSpec spec;
                spec.prepared = baking::prepareBakedScene(lighting::Scene(*scene));  // suite scenes may have lightmaps
                spec.referenceKey = spec.errorKey = sceneId;
                return makeBenchFrame(std::move(spec));
              }),
              false);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "render_bench: %s not registered: %s\n", sceneId.c_str(), e.what());
    }
  }
}

}  // namespace bench
