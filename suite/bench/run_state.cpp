#include "suite/bench/run_state.h"

#include "imaging/atomic_file.h"
#include "reference/reference_renderer.h"
#include "suite/bench/error_fingerprint.h"

#include <OpenImageIO/oiioversion.h>

#include <xxhash.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>
#include <unistd.h>

namespace bench {

namespace fs = std::filesystem;

backends::Backend& RunState::backendFor(const BenchFrame& bench) {
  if (!bench.spec.fullShader) return *specialised;
  if (!full) {
    backends::BackendOptions fullOptions = options;
    fullOptions.variant.specialised = false;
    full = entry->create(fullOptions);
  }
  return *full;
}

namespace {

// The cache file of a reference key: every byte outside [A-Za-z0-9.-] as
// "_" ("lights64-1280x720/srp" -> "lights64-1280x720_srp.ideal").
fs::path idealCacheFile(const fs::path& dir, const std::string& key) {
  std::string name;
  for (const char c : key) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-';
    name += ok ? c : '_';
  }
  return dir / (name + ".ideal");
}

// The file holds width, height, channels (int32) then the floats, bit for
// bit what the renderer returned: a cached reference is the rendered one.
void writeIdeal(const fs::path& file, const imaging::Image& image) {
  const std::int32_t header[3] = {image.width, image.height, image.channels};
  std::string bytes(reinterpret_cast<const char*>(header), sizeof header);
  bytes.append(reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size() * sizeof(float));
  fs::create_directories(file.parent_path());
  imaging::writeFileAtomically(file, bytes);  // processes at once may write the same key: each whole
}

std::optional<imaging::Image> readIdeal(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::int32_t header[3] = {};
  if (!in || !in.read(reinterpret_cast<char*>(header), sizeof header)) return std::nullopt;
  if (header[0] <= 0 || header[1] <= 0 || header[2] <= 0) return std::nullopt;
  imaging::Image image(header[0], header[1], header[2]);
  const auto size = std::streamsize(image.pixels.size() * sizeof(float));
  if (!in.read(reinterpret_cast<char*>(image.pixels.data()), size) || in.peek() != EOF) return std::nullopt;
  return image;
}

}  // namespace

const imaging::Image& RunState::idealFor(const BenchFrame& bench) {
  const BenchFrameSpec& spec = bench.spec;
  auto it = ideal.find(spec.referenceKey);
  const fs::path cacheFile =
      settings.idealCache.empty() ? fs::path() : idealCacheFile(settings.idealCache, spec.referenceKey);
  if (it == ideal.end() && !cacheFile.empty())
    if (std::optional<imaging::Image> cached = readIdeal(cacheFile))
      it = ideal.emplace(spec.referenceKey, std::move(*cached)).first;
  if (it == ideal.end()) {
    // The error baseline needs the value and its mask, not the tolerance.
    const reference::ReferenceOptions idealOptions{.ideal = true, .valueOnly = true};
    if (spec.referencePrepared) {
      const reference::ReferenceRenderer renderer(spec.referencePrepared);
      const lighting::Frame frame = lighting::prepareFrame(spec.referencePrepared, bench.frame.index);
      it = ideal.emplace(spec.referenceKey, renderer.render(frame, idealOptions).value).first;
    } else {
      const reference::ReferenceRenderer renderer(spec.prepared);
      it = ideal.emplace(spec.referenceKey, renderer.render(bench.frame, idealOptions).value).first;
    }
    if (!cacheFile.empty()) writeIdeal(cacheFile, it->second);
  }
  return it->second;
}

const ImageError& RunState::errorFor(const BenchFrame& bench, const std::function<imaging::Image()>& readback) {
  auto it = errors.find(bench.spec.errorKey);
  if (it != errors.end()) return it->second;
  const imaging::Image image = readback();
  const std::string key = contentKey(bench.spec.referenceKey, image);
  std::optional<ImageError> error = errorByContent(key);
  if (!error) {
    error = compareToIdeal(image, idealFor(bench));
    keepErrorByContent(key, *error);
  }
  return errors.emplace(bench.spec.errorKey, *error).first->second;
}

std::string RunState::contentKey(const std::string& referenceKey, const imaging::Image& image) {
  XXH3_state_t* state = XXH3_createState();
  XXH3_128bits_reset(state);
  const std::int32_t header[3] = {image.width, image.height, image.channels};
  XXH3_128bits_update(state, header, sizeof header);
  XXH3_128bits_update(state, image.pixels.data(), image.pixels.size() * sizeof(float));
  const XXH128_hash_t hash = XXH3_128bits_digest(state);
  XXH3_freeState(state);
  char hex[33];
  std::snprintf(hex, sizeof hex, "%016llx%016llx", static_cast<unsigned long long>(hash.high64),
                static_cast<unsigned long long>(hash.low64));
  return referenceKey + "@" + hex;
}

namespace {

// Where an error of this content is kept: under --error_cache, in the
// folder of this build's sources and OpenImageIO's version (compare_Yee's
// code), else beside this run's ideals; empty when neither is given.
fs::path errorFile(const Settings& settings, const std::string& contentKey) {
  if (!settings.errorCache.empty()) {
    const std::string folder = std::string(kErrorSourceFingerprint).append("-oiio-").append(OIIO_VERSION_STRING);
    return idealCacheFile(settings.errorCache / folder, contentKey).replace_extension(".error");
  }
  if (settings.idealCache.empty()) return {};
  return idealCacheFile(settings.idealCache, contentKey).replace_extension(".error");
}

}  // namespace

std::optional<ImageError> RunState::errorByContent(const std::string& key) const {
  if (auto it = errorsByContent.find(key); it != errorsByContent.end()) return it->second;
  const fs::path file = errorFile(settings, key);
  if (file.empty()) return std::nullopt;
  std::ifstream in(file);
  std::string fields[7];
  for (std::string& f : fields)
    if (!(in >> f)) return std::nullopt;
  // strtod reads "nan" and "inf" too (a broken frame's error).
  double v[7];
  for (int k = 0; k < 7; ++k) {
    char* end = nullptr;
    v[k] = std::strtod(fields[k].c_str(), &end);
    if (end == fields[k].c_str() || *end != '\0') return std::nullopt;
  }
  ImageError e;
  e.rmse = v[0], e.maxAbs = v[1], e.peak = v[2], e.psnrDb = v[3], e.perceptualFail = v[4];
  e.comparedPixels = std::int64_t(v[5]), e.nonFinitePixels = std::int64_t(v[6]);
  return e;
}

void RunState::keepErrorByContent(const std::string& key, const ImageError& e) {
  errorsByContent[key] = e;
  const fs::path file = errorFile(settings, key);
  if (file.empty()) return;
  char text[512];
  std::snprintf(text, sizeof text, "%.17g %.17g %.17g %.17g %.17g %lld %lld\n", e.rmse, e.maxAbs, e.peak, e.psnrDb,
                e.perceptualFail, static_cast<long long>(e.comparedPixels), static_cast<long long>(e.nonFinitePixels));
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);  // a file that cannot be kept costs a compare_Yee later, nothing else
  try {
    imaging::writeFileAtomically(file, text);  // processes at once may write the same key: each whole
  } catch (const std::exception&) {
    // not kept: a later run computes it again
  }
}

void useFreshPipelineCache(RunState& run) {
  // Appended, not `"literal" + std::string&&`: GCC 12 warns falsely (-Wrestrict) on that.
  const std::string name = std::string("lightcts-render-bench-cache-").append(std::to_string(::getpid()));
  run.cacheDir = fs::temp_directory_path() / name;
  fs::remove_all(run.cacheDir);
  fs::create_directories(run.cacheDir);
  ::setenv("LIGHTCTS_CACHE_DIR", run.cacheDir.c_str(), 1);
}

void emptyPipelineCache(const RunState& run) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(run.cacheDir, ec)) fs::remove_all(entry.path(), ec);
}

}  // namespace bench
