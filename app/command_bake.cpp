#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "baking/bake.h"
#include "baking/overlap_map.h"
#include "imaging/atomic_file.h"
#include "imaging/image_codec_loader.h"
#include "imaging/image_files.h"
#include "scene_input/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>
#include <set>

namespace app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// One lightmapped object's outputs, computed before anything is written.
struct ObjectOutput {
  int object = -1;
  std::string fileStem;  // <object-name>, made safe for a file name
  baking::OverlapMap overlap;
};

// The object's name when it is a plain file name; otherwise characters
// outside [A-Za-z0-9._-] become '_', and a name that is empty, starts with
// '.' or repeats an earlier one gets "-<object index>" (bake.json lists the
// files, so nothing has to be guessed).
std::string fileStemOf(const std::string& name, int object, std::set<std::string>& taken) {
  std::string stem;
  for (char c : name) stem += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ? c : '_';
  if (stem.empty() || stem.front() == '.' || taken.count(stem)) {
    // "a", "a-2", "a" must not give "a-2" twice: suffix until unused.
    const std::string base = stem + '-' + std::to_string(object);
    stem = base;
    for (int extra = 2; taken.count(stem); ++extra) stem = base + '-' + std::to_string(extra);
  }
  taken.insert(stem);
  return stem;
}

imaging::Image lightmapImage(const lighting::TexelMap& map) {
  imaging::Image image(map.resolution, map.resolution, 3);
  for (std::size_t t = 0; t < std::size_t(map.resolution) * std::size_t(map.resolution); ++t)
    for (std::size_t c = 0; c < 3; ++c) image.pixels[t * 3 + c] = map.texels[t * 4 + c];
  return image;
}

imaging::Image shadowMaskImage(const lighting::TexelMap& map) {
  imaging::Image image(map.resolution, map.resolution, 4);
  image.pixels = map.texels;
  return image;
}

// The overlap map as an exact 8-bit PNG in the legend's colours (the preview
// writer tone-maps, which would shift them). Texel (i, j) is pixel (i, j):
// row 0 is v = 0, the plane's local -Z edge.
void writeOverlapPng(const fs::path& path, const baking::OverlapMap& map) {
  const int n = map.resolution;
  std::vector<std::uint8_t> bytes(std::size_t(n) * std::size_t(n) * 3);
  for (std::size_t t = 0; t < map.counts.size(); ++t) {
    const baking::Rgb8 colour = baking::overlapColour(map.counts[t]);
    for (std::size_t c = 0; c < 3; ++c) bytes[t * 3 + c] = colour[c];
  }
  imaging::writePng8(path.string(), n, n, 3, bytes);
}

Json shadowMaskJson(const lighting::PreparedScene& prepared) {
  Json entries = Json::array();
  for (const lighting::ShadowMaskEntry& e : prepared.shadowMask.entries)
    entries.push_back({{"light", e.light},
                       {"name", prepared.scene.lights[std::size_t(e.light)].name},
                       {"channel", e.channel},
                       {"demoted", e.demoted}});
  return entries;
}

}  // namespace

// docs/cli.md, docs/baking.md: per lightmapped object
// DIR/<name>.lightmap.exr (RGB irradiance), DIR/<name>.shadowmask.exr (RGBA
// visibility per channel) and DIR/<name>.overlap.png; then DIR/bake.json.
// The bake (or the cache read) and the overlap maps are finished before the
// first file is written, and bake.json comes last: a folder with bake.json in
// it is complete.
int runBakeCommand(const BakeArguments& args, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    auto prepared = lighting::prepareScene(scene_input::loadSceneFile(args.scenePath));
    if (!prepared->needsBake())
      throw InputError(args.scenePath +
                       ": nothing to bake: no object is static with lightmap_resolution > 0 (lightmaps are for "
                       "static planes, SPEC 2)");
    baking::BakeOptions options;
    options.useCache = !args.noCache;
    const auto baked = baking::bakeScene(*prepared, options);

    const lighting::Scene& scene = prepared->scene;
    std::vector<ObjectOutput> outputs;
    std::set<std::string> taken;
    for (int o = 0; o < int(scene.objects.size()); ++o) {
      if (!scene.objects[std::size_t(o)].hasLightmap()) continue;
      outputs.push_back(
          {o, fileStemOf(scene.objects[std::size_t(o)].name, o, taken), baking::mixedLightOverlap(*prepared, o)});
    }

    imaging::requireImageModule();
    makeOutputDirectory(args.outDir);
    const fs::path dir(args.outDir);
    // bake.json, written last, marks a complete folder: an old one must not
    // vouch for maps this run fails to write.
    std::error_code ignored;
    fs::remove(dir / "bake.json", ignored);
    Json objects = Json::array();
    int maxOverlap = 0;
    long long conflicts = 0;
    for (const ObjectOutput& o : outputs) {
      const lighting::ObjectBake& bake = baked->objects[std::size_t(o.object)];
      const std::string lightmapFile = o.fileStem + ".lightmap.exr";
      const std::string maskFile = o.fileStem + ".shadowmask.exr";
      const std::string overlapFile = o.fileStem + ".overlap.png";
      imaging::writeExr((dir / lightmapFile).string(), lightmapImage(bake.lightmap));
      imaging::writeExr((dir / maskFile).string(), shadowMaskImage(bake.shadowMask));
      writeOverlapPng(dir / overlapFile, o.overlap);
      maxOverlap = std::max(maxOverlap, o.overlap.maxCount);
      conflicts += o.overlap.texelsOverLimit;
      objects.push_back({{"name", scene.objects[std::size_t(o.object)].name},
                         {"object", o.object},
                         {"resolution", o.overlap.resolution},
                         {"max_overlap", o.overlap.maxCount},
                         {"texels_over_4", o.overlap.texelsOverLimit},
                         {"lightmap", lightmapFile},
                         {"shadow_mask", maskFile},
                         {"overlap", overlapFile}});
    }
    Json demoted = Json::array();
    for (const lighting::ShadowMaskEntry& e : prepared->shadowMask.entries)
      if (e.demoted) demoted.push_back(scene.lights[std::size_t(e.light)].name);
    const Json report = {{"scene", scene.name},
                         {"scene_file", args.scenePath},
                         {"baker_version", baking::kBakerVersion},
                         {"cache_key", baked->cacheKey},
                         {"from_cache", baked->fromCache},
                         {"bake_milliseconds", baked->bakeMilliseconds},
                         {"objects", objects},
                         {"shadow_mask", shadowMaskJson(*prepared)},
                         {"demoted", demoted}};
    imaging::writeFileAtomically(dir / "bake.json", report.dump(2) + "\n");

    out << "bake: " << scene.name << ": " << outputs.size() << " lightmapped object(s), "
        << (baked->fromCache ? "read from the cache" : "baked") << " (bake took " << baked->bakeMilliseconds
        << " ms), max overlap " << maxOverlap << ", " << conflicts << " texel(s) reached by more than "
        << baking::kOverlapChannelLimit << " mixed shadowed lights, " << demoted.size()
        << " light(s) demoted; written to " << args.outDir << "\n";
    return kExitSuccess;
  });
}

}  // namespace app
