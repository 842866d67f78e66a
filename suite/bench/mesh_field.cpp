// The mesh field (`meshes64-<W>x<H>`): the 64-light field with real meshes
// instead of its boxes. Eight copies of Debian's assimp-testmodels
// 2CylinderEngine.glb (110,342 triangles each, about 880,000 in all, a
// game frame's count) stand on the tiles, imported as SPEC 2.1 imports them;
// half of the 64 lights are spots pointing down. Every light path is timed
// on it (all-lights, per-object, legacy-4+4, clustered, deferred in each
// buffer) beside the synthetic field, each against its own ideal; the page
// shows each frame's triangle count. Without the package the family is left
// out with a note on stderr (scripts/setup.sh installs it).
#include "scene_input/gltf_import.h"
#include "suite/bench/bench_families.h"
#include "suite/bench/bench_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <filesystem>
#include <vector>

namespace bench {
namespace {

using namespace lighting;

constexpr const char* kEngineFile = "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
// 0.0012 makes the engine 0.89 x 0.33 x 0.32 units: under the lights, which
// stand 0.4 above the tiles, and clear of the cell centres below them.
constexpr double kEngineScale = 0.0012;
// The engine's lowest point is y = -181 in the file: raised onto the floor.
constexpr double kEngineLift = 181 * kEngineScale;

std::string meshFieldSceneName(const RunState& run) {
  const FieldSize size = fieldSize(run);
  return "meshes64-" + std::to_string(size.width) + "x" + std::to_string(size.height);
}

// The engines on every other box corner of the field (8 of the 16), each
// turned by its own angle: imported once, shared by every mode's scene.
std::vector<Object> engines(const FieldSize& size) {
  FieldSpec field;
  const double fieldX = kFieldZ * size.width / size.height;
  const double tileX = fieldX / field.tileColumns, tileZ = kFieldZ / field.tileRows;
  std::vector<Object> objects;
  int placed = 0;
  for (int i = 1; i < field.tileColumns; i += 2) {
    for (int k = 1; k < field.tileRows; k += 2) {
      if ((i + k) % 4 != 2) continue;  // every other corner
      scene_input::GltfImportRequest request;
      request.file = kEngineFile;
      const glm::dvec3 at(-fieldX / 2 + i * tileX, kEngineLift, -kFieldZ / 2 + k * tileZ);
      request.transform = glm::translate(glm::dmat4(1.0), at) *
                          glm::rotate(glm::dmat4(1.0), glm::radians(37.0 * placed), glm::dvec3(0, 1, 0)) *
                          glm::scale(glm::dmat4(1.0), glm::dvec3(kEngineScale));
      for (const scene_input::ImportedPrimitive& primitive : scene_input::importGltf(request).primitives) {
        Object object;
        object.name = "engine" + std::to_string(placed) + "/" + primitive.name;
        object.mesh.type = MeshType::Imported;
        object.mesh.imported = primitive.mesh;
        // Lambert with the file's base colour, so that the legacy profile
        // (diffuse only) draws the same materials as the others.
        object.albedo = primitive.baseColor;
        objects.push_back(std::move(object));
      }
      ++placed;
    }
  }
  return objects;
}

// The field of `mode` without its boxes, with the engines, and with the
// lights of every other grid cell (a checkerboard) as spots pointing down.
Scene meshFieldScene(FrameMode mode, const FieldSize& size, const std::vector<Object>& meshes, const std::string& name) {
  FieldSpec field;
  field.width = size.width;
  field.height = size.height;
  field.mode = mode;
  field.boxes = false;
  Scene s = fieldScene(field, name);
  s.objects.insert(s.objects.end(), meshes.begin(), meshes.end());
  for (int i = 0; i < field.lightColumns; ++i) {
    for (int k = 0; k < field.lightRows; ++k) {
      Light& light = s.lights[std::size_t(i * field.lightRows + k)];  // fieldScene's order: columns, then rows
      if ((i + k) % 2 == 0) continue;
      light.type = LightType::Spot;
      light.direction = {0, -1, 0};
      light.spotAngleDeg = kFieldSpotAngleDeg;
      light.innerSpotAngleDeg = kFieldSpotInnerAngleDeg;
    }
  }
  return s;
}

}  // namespace

NamedFrames meshFieldModes(const RunState& run) {
  if (!std::filesystem::exists(kEngineFile)) {
    std::fprintf(stderr, "render_bench: %s is missing (Debian's assimp-testmodels): the mesh field is left out\n",
                 kEngineFile);
    return {};
  }
  const std::string scene = meshFieldSceneName(run);
  const FieldSize size = fieldSize(run);
  // The engines are imported once, by the first mode a filter keeps; the
  // deferred modes' ideal is the forward field's scene.
  const SharedOnDemand<std::vector<Object>> meshes([size] { return engines(size); });
  const SharedOnDemand<std::shared_ptr<const PreparedScene>> forward([meshes, size, scene] {
    return prepareScene(meshFieldScene(FrameMode::AllLights, size, meshes.get(), scene + "-" + modeName(FrameMode::AllLights)));
  });
  NamedFrames frames;
  const FrameMode modes[] = {FrameMode::AllLights,     FrameMode::PerObject,     FrameMode::Legacy4x4,
                             FrameMode::Clustered,     FrameMode::DeferredHdr32, FrameMode::DeferredHdr16,
                             FrameMode::DeferredLdr8};
  for (const FrameMode mode : modes) {
    if (run.settings.quick && mode != FrameMode::AllLights && mode != FrameMode::PerObject) continue;
    frames.emplace_back(modeName(mode), lazyBenchFrame(true, [grid = run.settings.clusterGrid, meshes, forward, size,
                                                              scene, mode] {
      BenchFrameSpec spec;
      spec.prepared = mode == FrameMode::AllLights
                          ? forward.get()
                          : prepareScene(meshFieldScene(mode, size, meshes.get(), scene + "-" + modeName(mode)));
      const bool legacy = mode == FrameMode::Legacy4x4;
      spec.referenceKey = scene + (legacy ? "/legacy" : "/srp");
      if (deferredBufferOf(mode)) spec.referencePrepared = forward.get();
      spec.errorKey = scene + "/" + modeName(mode);
      spec.everyLightInView = true;
      if (mode == FrameMode::Clustered) spec.clusters = grid;
      return makeBenchFrame(std::move(spec));
    }));
  }
  return frames;
}

void registerMeshFieldModes(Registrar& r, const NamedFrames& frames) {
  const std::string scene = meshFieldSceneName(r.run());
  for (const auto& [mode, bench] : frames) r.frame(scene, mode, "", bench, false);
}

}  // namespace bench
