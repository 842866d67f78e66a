#include "conformance/reference_cache.h"

#include "baking/byte_stream.h"
#include "baking/sha256.h"
#include "conformance/reference_fingerprint.h"  // generated (CMakeLists.txt)
#include "imaging/atomic_file.h"
#include "lighting/mesh.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <xxhash.h>

namespace conformance {
namespace {

namespace fs = std::filesystem;
using baking::ByteReader;
using baking::ByteWriter;

// The file: magic, format version, key (hex), the counts, then the images
// (value, tolerance, shadow intervals: width, height, channels, floats each),
// and an XXH3 checksum of every byte before it (against damage; the key
// guards against another scene). Bump the version when the layout changes.
constexpr char kMagic[8] = {'L', 'C', 'T', 'S', 'R', 'E', 'F', 'S'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::size_t kKeyLength = 64;  // hex SHA-256
constexpr std::size_t kChecksumSize = 8;
constexpr int kLargestSide = 16384;     // a corrupt header must not ask for terabytes

std::vector<std::uint8_t> readWholeFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeImage(ByteWriter& w, const imaging::Image& image) {
  w.i32(image.width);
  w.i32(image.height);
  w.i32(image.channels);
  w.floats(image.pixels);
}

bool readImage(ByteReader& r, imaging::Image& image) {
  image.width = std::int32_t(r.u32());
  image.height = std::int32_t(r.u32());
  image.channels = std::int32_t(r.u32());
  if (r.failed() || image.width < 0 || image.height < 0 || image.channels < 0 || image.width > kLargestSide ||
      image.height > kLargestSide || image.channels > 4)
    return false;
  return r.floats(image.pixels, std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels));
}

std::vector<std::uint8_t> serialise(const std::string& key, const reference::ReferenceImages& images) {
  ByteWriter w;
  w.raw(kMagic, sizeof(kMagic));
  w.u32(kFormatVersion);
  w.text(key);
  w.u64(std::uint64_t(images.lightEvaluations));
  w.u64(std::uint64_t(images.maskedPixels));
  w.u64(std::uint64_t(images.shadowedPixels));
  w.u64(std::uint64_t(images.ambiguousShadowPixels));
  writeImage(w, images.value);
  writeImage(w, images.tolerance);
  writeImage(w, images.shadowInterval);
  std::vector<std::uint8_t> bytes = w.bytes();
  const std::uint64_t checksum = XXH3_64bits(bytes.data(), bytes.size());
  for (int i = 0; i < 8; ++i) bytes.push_back(std::uint8_t(checksum >> (8 * i)));
  return bytes;
}

std::optional<reference::ReferenceImages> parse(const std::vector<std::uint8_t>& bytes, const std::string& key) {
  if (bytes.size() < kChecksumSize) return std::nullopt;
  const std::size_t body = bytes.size() - kChecksumSize;
  ByteReader trailer(bytes.data() + body, kChecksumSize);
  if (trailer.u64() != XXH3_64bits(bytes.data(), body)) return std::nullopt;
  ByteReader r(bytes.data(), body);
  for (char c : kMagic)
    if (r.u8() != std::uint8_t(c)) return std::nullopt;
  if (r.u32() != kFormatVersion || r.text(kKeyLength) != key) return std::nullopt;
  reference::ReferenceImages images;
  images.lightEvaluations = std::int64_t(r.u64());
  images.maskedPixels = std::int64_t(r.u64());
  images.shadowedPixels = std::int64_t(r.u64());
  images.ambiguousShadowPixels = std::int64_t(r.u64());
  if (!readImage(r, images.value) || !readImage(r, images.tolerance) || !readImage(r, images.shadowInterval))
    return std::nullopt;
  if (r.failed() || r.remaining() != 0) return std::nullopt;
  return images;
}

std::optional<reference::ReferenceImages> readCached(const fs::path& file, const std::string& key) {
  try {
    return parse(readWholeFile(file), key);
  } catch (const std::exception&) {
    return std::nullopt;  // e.g. out of memory for a damaged size: render instead
  }
}

// An exclusive flock(2) on DIR/KEY.lock for as long as it lives; none when
// the file cannot be opened (then two workers may both render, which costs
// time, never correctness: the file is replaced whole).
class KeyLock {
 public:
  explicit KeyLock(const fs::path& file) : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~KeyLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  KeyLock(const KeyLock&) = delete;
  KeyLock& operator=(const KeyLock&) = delete;

 private:
  int fd_;
};

}  // namespace

fs::path defaultReferenceCacheDirectory() {
  if (const char* dir = std::getenv("LIGHTCTS_CACHE_DIR"); dir && *dir) return fs::path(dir) / "references";
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "lightcts" / "references";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "lightcts" / "references";
  return {};
}

std::string sceneContentDigest(const fs::path& sceneFile, const lighting::Scene& scene) {
  ByteWriter w;
  const std::vector<std::uint8_t> file = readWholeFile(sceneFile);
  w.u64(file.size());
  w.raw(file.data(), file.size());
  // Imported meshes (SPEC 2.1) come from files beside the scene: their
  // triangles, as imported, are part of what the reference reads.
  for (const lighting::Object& object : scene.objects) {
    if (object.mesh.type != lighting::MeshType::Imported) continue;
    const lighting::Mesh& mesh = *object.mesh.imported;
    const auto vec3 = [&w](const lighting::Vec3& v) {
      w.f64(v.x);
      w.f64(v.y);
      w.f64(v.z);
    };
    w.u64(mesh.positions.size());
    for (const lighting::Vec3& p : mesh.positions) vec3(p);
    for (const lighting::Vec3& n : mesh.normals) vec3(n);
    w.u64(mesh.triangles.size());
    for (const auto& t : mesh.triangles) vec3(lighting::Vec3(t));
    for (std::uint32_t piece : mesh.trianglePiece) w.u64(piece);
  }
  for (const lighting::Light& light : scene.lights) {
    if (!light.cookie) continue;
    for (const auto& image : light.cookie->images) {
      w.i32(image->width);
      w.i32(image->height);
      w.floats(image->texels);
    }
  }
  return baking::toHex(baking::sha256(w.bytes().data(), w.bytes().size()));
}

std::string referenceCacheKey(const std::string& sceneDigest, int frame, const reference::ReferenceOptions& options) {
  ByteWriter w;
  w.text("lightcts-reference");
  w.text(kReferenceSourceFingerprint);
  w.text(sceneDigest);
  w.i32(frame);
  w.boolean(options.ideal);
  w.boolean(options.bakedLightsRealtime);
  w.f64(options.filterWeightPrecision);
  w.i32(options.subPixelPrecisionBits);
  w.boolean(options.keepShadowIntervals);
  w.boolean(options.valueOnly);  // no tolerance in it
  return baking::toHex(baking::sha256(w.bytes().data(), w.bytes().size()));
}

bool cacheable(const reference::ReferenceOptions& options) {
  return !options.keepExactValues && !options.keepToleranceTerms && !options.keepLightPart;
}

reference::ReferenceImages cachedReference(const fs::path& directory, const std::string& key,
                                           const std::function<reference::ReferenceImages()>& render, bool* hit) {
  if (hit) *hit = false;
  std::error_code ec;
  if (directory.empty() || key.size() != kKeyLength || (fs::create_directories(directory, ec), ec)) return render();
  const fs::path file = directory / (key + ".ref");
  if (auto cached = readCached(file, key)) {
    if (hit) *hit = true;
    return std::move(*cached);
  }
  const KeyLock lock(directory / (key + ".lock"));
  if (auto cached = readCached(file, key)) {  // rendered by another worker while this one waited
    if (hit) *hit = true;
    return std::move(*cached);
  }
  reference::ReferenceImages images = render();
  try {
    const std::vector<std::uint8_t> bytes = serialise(key, images);
    imaging::writeFileAtomically(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  } catch (const std::exception&) {
    // A full disk or a read-only cache: the next worker renders it again.
  }
  return images;
}

}  // namespace conformance
