#include "baking/bake_cache.h"

#include "baking/byte_stream.h"
#include "baking/sha256.h"
#include "baking/source_fingerprint.h"  // generated (CMakeLists.txt)
#include "imaging/atomic_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string_view>

#include <xxhash.h>

namespace baking {
namespace {

namespace fs = std::filesystem;

// The file: magic, format version, key (hex), object count, each object's
// resolution (0: no maps), the bake's milliseconds, the texels of every
// object with maps (lightmap, then shadow mask, N * N * 4 floats each), and a
// checksum of every byte before it. Bump the version when the layout changes.
// Version 2: the checksum is XXH3. A version 1 file (FNV-1a over 64-bit
// words) fails the checksum (or else the version) and is a miss.
constexpr char kMagic[8] = {'L', 'C', 'T', 'S', 'B', 'A', 'K', 'E'};
constexpr std::uint32_t kFormatVersion = 2;
constexpr std::size_t kKeyLength = 64;  // hex SHA-256
constexpr std::size_t kChecksumSize = 8;

// The file's checksum guards against damage, not against an adversary (the
// key guards against another scene), so it is a fast non-cryptographic hash:
// XXH3's 64-bit hash (libxxhash). FNV-1a over 64-bit words, the obvious
// hand-written choice, misses any two flipped bit-63s of words (two texels'
// sign bits: baking/tests/bake_cache_test.cpp shows why), and XXH3 is faster:
// over 8 MiB (a 512 x 512 bake) 0.5 ms against FNV's 3.4 ms on the
// development machine.
std::uint64_t contentChecksum(const std::uint8_t* data, std::size_t size) { return XXH3_64bits(data, size); }

void writeVec3(ByteWriter& w, const lighting::Vec3& v) {
  w.f64(v.x);
  w.f64(v.y);
  w.f64(v.z);
}

// Every field of the spec, whatever the mesh type, so the serialisation does
// not depend on which fields a type reads; then the generated triangles and
// the world transform themselves, so a change to the mesh generator or the
// transform convention also misses, even if nobody bumps kBakerVersion.
void writeObject(ByteWriter& w, const lighting::Object& object, const lighting::ObjectGeometry& geometry) {
  const lighting::MeshSpec& m = object.mesh;
  w.u32(std::uint32_t(m.type));
  w.f64(m.planeSizeX);
  w.f64(m.planeSizeZ);
  w.i32(m.subdivisions);
  w.f64(m.sphereRadius);
  w.i32(m.sphereSegments);
  w.i32(m.sphereRings);
  writeVec3(w, m.boxSize);
  writeVec3(w, object.transform.translate);
  writeVec3(w, object.transform.rotateDeg);
  w.f64(object.transform.scale);
  w.boolean(object.isStatic);
  w.i32(object.lightmapResolution);

  for (int c = 0; c < 3; ++c) writeVec3(w, geometry.transform.rotation[c]);
  w.f64(geometry.transform.scale);
  writeVec3(w, geometry.transform.translate);
  w.u64(geometry.mesh.positions.size());
  for (const lighting::Vec3& p : geometry.mesh.positions) writeVec3(w, p);
  w.u64(geometry.mesh.triangles.size());
  for (const glm::u32vec3& t : geometry.mesh.triangles) {
    w.u32(t.x);
    w.u32(t.y);
    w.u32(t.z);
  }
}

// Every field but the name, which changes no texel.
void writeLight(ByteWriter& w, const lighting::Light& light) {
  w.u32(std::uint32_t(light.type));
  writeVec3(w, light.position);
  writeVec3(w, light.direction);
  w.f64(light.range);
  w.f64(light.spotAngleDeg);
  w.boolean(light.innerSpotAngleDeg.has_value());
  w.f64(light.innerSpotAngleDeg.value_or(0.0));
  writeVec3(w, light.color);
  w.f64(light.intensity);
  w.u32(std::uint32_t(light.mode));
  w.boolean(light.shadows);
  w.f64(light.shadowStrength);
  w.u32(std::uint32_t(light.bakeFalloff));
}

std::vector<int> expectedResolutions(const lighting::PreparedScene& prepared) {
  std::vector<int> resolutions;
  for (const lighting::Object& o : prepared.scene.objects)
    resolutions.push_back(o.hasLightmap() ? o.lightmapResolution : 0);
  return resolutions;
}

std::size_t texelCount(int resolution) { return std::size_t(resolution) * std::size_t(resolution) * 4; }

std::vector<std::uint8_t> readWholeFile(const fs::path& path, std::size_t expectedSize) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec || size != expectedSize) return {};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::vector<std::uint8_t> bytes(expectedSize);
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(expectedSize));
  if (std::size_t(in.gcount()) != expectedSize) return {};
  return bytes;
}

std::shared_ptr<const lighting::BakedLighting> parseCacheFile(const std::vector<std::uint8_t>& bytes,
                                                              const std::string& key,
                                                              const std::vector<int>& resolutions) {
  if (bytes.size() < kChecksumSize) return nullptr;
  const std::size_t body = bytes.size() - kChecksumSize;
  ByteReader trailer(bytes.data() + body, kChecksumSize);
  if (trailer.u64() != contentChecksum(bytes.data(), body)) return nullptr;

  ByteReader r(bytes.data(), body);
  for (char c : kMagic)
    if (r.u8() != std::uint8_t(c)) return nullptr;
  if (r.u32() != kFormatVersion) return nullptr;
  if (r.text(kKeyLength) != key) return nullptr;
  if (r.u32() != resolutions.size()) return nullptr;
  for (int resolution : resolutions)
    if (r.u32() != std::uint32_t(resolution)) return nullptr;
  auto baked = std::make_shared<lighting::BakedLighting>();
  baked->bakeMilliseconds = r.f64();
  if (r.failed() || !std::isfinite(baked->bakeMilliseconds) || baked->bakeMilliseconds < 0) return nullptr;
  baked->objects.resize(resolutions.size());
  for (std::size_t o = 0; o < resolutions.size(); ++o) {
    const int n = resolutions[o];
    if (n == 0) continue;
    lighting::ObjectBake& bake = baked->objects[o];
    bake.lightmap.resolution = n;
    bake.shadowMask.resolution = n;
    if (!r.floats(bake.lightmap.texels, texelCount(n)) || !r.floats(bake.shadowMask.texels, texelCount(n)))
      return nullptr;
  }
  if (r.failed() || r.remaining() != 0) return nullptr;
  baked->cacheKey = key;
  baked->fromCache = true;
  return baked;
}

std::size_t cacheFileSize(const std::vector<int>& resolutions) {
  std::size_t size = sizeof(kMagic) + 4 + 8 + kKeyLength + 4 + 4 * resolutions.size() + 8 + kChecksumSize;
  for (int n : resolutions) size += 2 * texelCount(n) * sizeof(float);
  return size;
}

}  // namespace

std::string bakeCacheKey(const lighting::PreparedScene& prepared, const BakeOptions& options) {
  ByteWriter w;
  w.text("lightcts-bake");
  w.u32(kBakerVersion);
  w.text(kBakerSourceFingerprint);  // the code that computes texels, hashed at build time
  w.u32(std::uint32_t(prepared.scene.pipeline.profile));
  w.u64(prepared.scene.objects.size());
  for (std::size_t o = 0; o < prepared.scene.objects.size(); ++o)
    writeObject(w, prepared.scene.objects[o], prepared.objects[o]);
  w.u64(prepared.scene.lights.size());
  for (const lighting::Light& light : prepared.scene.lights) writeLight(w, light);
  w.u64(prepared.shadowMask.entries.size());
  for (const lighting::ShadowMaskEntry& e : prepared.shadowMask.entries) {
    w.i32(e.light);
    w.i32(e.channel);
    w.boolean(e.demoted);
  }
  w.boolean(options.mutantLegacyFalloff);
  return toHex(sha256(w.bytes().data(), w.bytes().size()));
}

fs::path bakeCacheDirectory(const BakeOptions& options) {
  if (!options.cacheDirectory.empty()) return options.cacheDirectory;
  // The root the Vulkan pipeline cache uses (backends/vulkan/pipeline_cache_file.cpp).
  if (const char* dir = std::getenv("LIGHTCTS_CACHE_DIR"); dir && *dir) return fs::path(dir) / "bakes";
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "lightcts" / "bakes";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "lightcts" / "bakes";
  return {};
}

fs::path bakeCacheFile(const std::string& key, const BakeOptions& options) {
  const fs::path dir = bakeCacheDirectory(options);
  if (dir.empty() || key.empty()) return {};
  return dir / (key + ".bake");
}

std::shared_ptr<const lighting::BakedLighting> readCachedBake(const std::string& key,
                                                               const lighting::PreparedScene& prepared,
                                                               const BakeOptions& options) {
  try {
    const fs::path path = bakeCacheFile(key, options);
    if (path.empty()) return nullptr;
    const std::vector<int> resolutions = expectedResolutions(prepared);
    const std::vector<std::uint8_t> bytes = readWholeFile(path, cacheFileSize(resolutions));
    if (bytes.empty()) return nullptr;
    return parseCacheFile(bytes, key, resolutions);
  } catch (const std::exception&) {
    return nullptr;  // e.g. out of memory for a huge file: bake instead
  }
}

bool writeCachedBake(const lighting::BakedLighting& baked, const BakeOptions& options) {
  try {
    const fs::path path = bakeCacheFile(baked.cacheKey, options);
    if (path.empty() || baked.cacheKey.size() != kKeyLength) return false;
    ByteWriter w;
    std::vector<int> resolutions;
    for (const lighting::ObjectBake& o : baked.objects) resolutions.push_back(o.lightmap.resolution);
    w.reserve(cacheFileSize(resolutions));
    w.raw(kMagic, sizeof(kMagic));
    w.u32(kFormatVersion);
    w.text(baked.cacheKey);
    w.u32(std::uint32_t(resolutions.size()));
    for (int n : resolutions) w.u32(std::uint32_t(n));
    w.f64(baked.bakeMilliseconds);
    for (const lighting::ObjectBake& o : baked.objects) {
      if (o.lightmap.resolution == 0) continue;
      const std::size_t count = texelCount(o.lightmap.resolution);
      if (o.shadowMask.resolution != o.lightmap.resolution || o.lightmap.texels.size() != count ||
          o.shadowMask.texels.size() != count)
        return false;
      w.floats(o.lightmap.texels);
      w.floats(o.shadowMask.texels);
    }
    w.u64(contentChecksum(w.bytes().data(), w.bytes().size()));

    // Atomic, so a parallel run reading the same key never sees half a file.
    imaging::writeFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(w.bytes().data()), w.bytes().size()));
    return true;
  } catch (const std::exception&) {
    // A cache that cannot be written only costs a re-bake next time.
    return false;
  }
}

}  // namespace baking
