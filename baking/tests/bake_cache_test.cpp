// The bake cache: a second bake reads the first's file; every input changes
// the key; damaged files are misses that re-bake, never errors.
#include "baking/bake_cache.h"
#include "baking/tests/test_scenes.h"
#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

namespace baking::testing {
namespace {

namespace fs = std::filesystem;

// The bake cache creates its folder (dir_/bakes) itself.
class BakeCacheTest : public imaging::testing::ScratchFolderTest {
 protected:
  BakeCacheTest() : ScratchFolderTest(false) {}
  void SetUp() override {
    ScratchFolderTest::SetUp();
    options_.cacheDirectory = (dir_ / "bakes").string();
  }

  static Scene scene() {
    Scene s;
    s.objects.push_back(lightmappedPlane(4, 4, 8));
    s.objects.push_back(box({1, 1, 1}, {0, 1, 0}));
    Light baked = pointLight({0.5, 3, 0.5}, 6, 2, LightMode::Baked, {1, 0.5, 0.2});
    baked.shadows = true;
    s.lights.push_back(baked);
    s.lights.push_back(mixedShadowed({-1, 2, 0}, 5, 1));
    return s;
  }

  std::shared_ptr<const lighting::BakedLighting> bake(const Scene& s) {
    return bakeScene(*lighting::prepareScene(s), options_);
  }
  std::string key(const Scene& s, const BakeOptions& o) { return bakeCacheKey(*lighting::prepareScene(s), o); }

  static void expectSameTexels(const lighting::BakedLighting& a, const lighting::BakedLighting& b) {
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t o = 0; o < a.objects.size(); ++o) {
      EXPECT_EQ(a.objects[o].lightmap.resolution, b.objects[o].lightmap.resolution);
      EXPECT_EQ(a.objects[o].lightmap.texels, b.objects[o].lightmap.texels);
      EXPECT_EQ(a.objects[o].shadowMask.resolution, b.objects[o].shadowMask.resolution);
      EXPECT_EQ(a.objects[o].shadowMask.texels, b.objects[o].shadowMask.texels);
    }
  }

  BakeOptions options_;
};

TEST_F(BakeCacheTest, SecondBakeReadsTheFirstFromTheCache) {
  const auto first = bake(scene());
  EXPECT_FALSE(first->fromCache);
  EXPECT_EQ(first->cacheKey.size(), 64u);
  EXPECT_TRUE(fs::is_regular_file(bakeCacheFile(first->cacheKey, options_)));
  const auto second = bake(scene());
  EXPECT_TRUE(second->fromCache);
  EXPECT_EQ(second->cacheKey, first->cacheKey);
  EXPECT_EQ(second->bakeMilliseconds, first->bakeMilliseconds);  // the original bake's time
  expectSameTexels(*first, *second);
  // No temporary file is left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(options_.cacheDirectory)) {
    ++files;
    EXPECT_EQ(entry.path().extension(), ".bake");
  }
  EXPECT_EQ(files, 1);
}

TEST_F(BakeCacheTest, NoCacheNeitherReadsNorWrites) {
  options_.useCache = false;
  const auto first = bake(scene());
  EXPECT_FALSE(first->fromCache);
  EXPECT_FALSE(first->cacheKey.empty());  // still reported
  EXPECT_FALSE(fs::exists(options_.cacheDirectory));
}

TEST_F(BakeCacheTest, EveryInputChangesTheKey) {
  const Scene base = scene();
  const std::string k = key(base, options_);
  EXPECT_EQ(key(base, options_), k);  // stable

  auto changed = [&](auto edit) {
    Scene s = base;
    edit(s);
    return key(s, options_);
  };
  EXPECT_NE(changed([](Scene& s) { s.lights[0].intensity = 2.5; }), k);
  EXPECT_NE(changed([](Scene& s) { s.lights[0].position.y += 1e-9; }), k);
  EXPECT_NE(changed([](Scene& s) { s.lights[0].bakeFalloff = lighting::BakeFalloff::Legacy; }), k);
  EXPECT_NE(changed([](Scene& s) { s.lights[0].shadows = false; }), k);
  EXPECT_NE(changed([](Scene& s) { s.lights[1].shadowStrength = 0.5; }), k);
  EXPECT_NE(changed([](Scene& s) { s.lights[0].innerSpotAngleDeg = 10; }), k);
  EXPECT_NE(changed([](Scene& s) { s.lights.push_back(s.lights[0]); }), k);
  EXPECT_NE(changed([](Scene& s) { std::swap(s.lights[0], s.lights[1]); }), k);
  EXPECT_NE(changed([](Scene& s) { s.objects[0].lightmapResolution = 16; }), k);
  EXPECT_NE(changed([](Scene& s) { s.objects[0].isStatic = false; }), k);
  EXPECT_NE(changed([](Scene& s) { s.objects[1].transform.translate.x = 0.25; }), k);
  EXPECT_NE(changed([](Scene& s) { s.objects[1].transform.rotateDeg.y = 10; }), k);
  EXPECT_NE(changed([](Scene& s) { s.objects[0].mesh.subdivisions = 2; }), k);
  EXPECT_NE(changed([](Scene& s) { s.objects[1].mesh.boxSize.y = 2; }), k);
  EXPECT_NE(changed([](Scene& s) { s.pipeline.profile = lighting::Profile::Legacy; }), k);
  // A second mixed light that overlaps the first takes channel 1: the
  // assignment is part of the key through the lights anyway; the option is too.
  BakeOptions mutant = options_;
  mutant.mutantLegacyFalloff = true;
  EXPECT_NE(key(base, mutant), k);
  // What changes no texel does not change the key.
  BakeOptions threads = options_;
  threads.threads = 1;
  EXPECT_EQ(key(base, threads), k);
  EXPECT_EQ(changed([](Scene& s) { s.lights[0].name = "renamed"; }), k);
  EXPECT_EQ(changed([](Scene& s) { s.objects[0].albedo = {0.5, 0.5, 0.5}; }), k);
}

TEST_F(BakeCacheTest, ChangedLightMissesAndBakesAgain) {
  const auto first = bake(scene());
  Scene brighter = scene();
  brighter.lights[0].intensity = 4;
  const auto second = bake(brighter);
  EXPECT_FALSE(second->fromCache);
  EXPECT_NE(second->cacheKey, first->cacheKey);
  // Twice the light, twice the irradiance (all texels with light).
  const auto& a = first->objects[0].lightmap.texels;
  const auto& b = second->objects[0].lightmap.texels;
  for (std::size_t k = 0; k < a.size(); k += 4) EXPECT_NEAR(b[k], 2 * a[k], 1e-6 * b[k]);
}

TEST_F(BakeCacheTest, MutantOptionMisses) {
  const auto first = bake(scene());
  options_.mutantLegacyFalloff = true;
  const auto mutant = bake(scene());
  EXPECT_FALSE(mutant->fromCache);
  EXPECT_NE(mutant->objects[0].lightmap.texels, first->objects[0].lightmap.texels);
}

class DamagedCacheTest : public BakeCacheTest, public ::testing::WithParamInterface<std::string> {};

// Each way a file can be wrong: the next bake is a miss, bakes the same
// texels again without throwing, and repairs the file.
TEST_P(DamagedCacheTest, DamagedFileIsAMissAndIsRewritten) {
  const auto first = bake(scene());
  const fs::path file = bakeCacheFile(first->cacheKey, options_);
  const auto size = fs::file_size(file);
  const std::string damage = GetParam();
  if (damage == "truncated") {
    fs::resize_file(file, size / 2);
  } else if (damage == "empty") {
    fs::resize_file(file, 0);
  } else if (damage == "extended") {
    std::ofstream(file, std::ios::binary | std::ios::app) << "x";
  } else if (damage == "flipped-texel" || damage == "flipped-header") {
    std::fstream f(file, std::ios::binary | std::ios::in | std::ios::out);
    const std::streamoff at = damage == "flipped-texel" ? std::streamoff(size / 2) : 9;
    f.seekg(at);
    char c = 0;
    f.get(c);
    f.seekp(at);
    f.put(char(c ^ 0x10));
  } else if (damage == "other-key") {
    // A valid file of another bake under this key's name.
    Scene other = scene();
    other.lights[0].intensity = 7;
    const auto otherBake = bake(other);
    fs::copy_file(bakeCacheFile(otherBake->cacheKey, options_), file, fs::copy_options::overwrite_existing);
  }
  std::shared_ptr<const lighting::BakedLighting> again;
  ASSERT_NO_THROW(again = bake(scene()));
  EXPECT_FALSE(again->fromCache);
  expectSameTexels(*first, *again);
  const auto third = bake(scene());
  EXPECT_TRUE(third->fromCache);
  expectSameTexels(*first, *third);
}

INSTANTIATE_TEST_SUITE_P(Damage, DamagedCacheTest,
                         ::testing::Values("truncated", "empty", "extended", "flipped-texel", "flipped-header",
                                           "other-key"));

// The checksum of format version 1: FNV-1a over 64-bit little-endian words. Kept here only to prove the damage below is its blind spot.
std::uint64_t fnv1aOverWords(const std::vector<std::uint8_t>& bytes, std::size_t size) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  std::size_t at = 0;
  for (; at + 8 <= size; at += 8) {
    std::uint64_t word = 0;
    for (int i = 0; i < 8; ++i) word |= std::uint64_t(bytes[at + std::size_t(i)]) << (8 * i);
    h = (h ^ word) * 0x100000001b3ull;
  }
  for (; at < size; ++at) h = (h ^ bytes[at]) * 0x100000001b3ull;
  return h;
}

// Two texels whose sign bits flip, each the upper float of an odd-numbered
// 64-bit word, so each flip is bit 63 of its word. FNV over words misses it:
// flipping bit 63 of a word w_i turns h_i ^ w_i into (h_i ^ w_i) + 2^63
// (mod 2^64), and (x + 2^63) * P = x * P + 2^63 * P = x * P + 2^63 for the odd
// prime P, so h_{i+1} differs in bit 63 alone. Every later step keeps that:
// XOR with an unchanged word leaves the difference at bit 63, and the odd
// multiply again maps +2^63 to +2^63. The second flip adds another 2^63, and
// 2^63 + 2^63 = 0 (mod 2^64): the final FNV is the same as the undamaged
// file's, while two texels have changed sign. XXH3 must see it.
TEST_F(BakeCacheTest, TwoFlippedSignBitsAtOddWordsAreAMiss) {
  const auto first = bake(scene());
  const fs::path file = bakeCacheFile(first->cacheKey, options_);
  std::vector<std::uint8_t> bytes(fs::file_size(file));
  std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  // The texels: the 8 x 8 lightmap and shadow mask, four floats a texel,
  // then the 8-byte checksum.
  const std::size_t checksumAt = bytes.size() - 8;
  const std::size_t texelsAt = checksumAt - 2 * 8 * 8 * 4 * sizeof(float);
  std::vector<std::size_t> flips;
  for (std::size_t at = texelsAt; at < checksumAt && flips.size() < 2; at += 4) {
    // Offset 12 mod 16: the upper half of an odd word; its byte 3 holds the
    // float's sign bit, which is the word's bit 63.
    float value = 0;
    std::memcpy(&value, &bytes[at], sizeof value);
    if (at % 16 == 12 && value != 0) flips.push_back(at);
  }
  ASSERT_EQ(flips.size(), 2u);
  std::vector<std::uint8_t> damaged = bytes;
  for (std::size_t at : flips) damaged[at + 3] ^= 0x80;
  ASSERT_NE(damaged, bytes);
  // The very damage an FNV-1a over 64-bit words cannot see (so the cache uses XXH3).
  ASSERT_EQ(fnv1aOverWords(damaged, checksumAt), fnv1aOverWords(bytes, checksumAt));
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(damaged.data()), std::streamsize(damaged.size()));

  std::shared_ptr<const lighting::BakedLighting> again;
  ASSERT_NO_THROW(again = bake(scene()));
  EXPECT_FALSE(again->fromCache);  // a miss: baked again
  expectSameTexels(*first, *again);
  const auto third = bake(scene());
  EXPECT_TRUE(third->fromCache);  // and the file was rewritten
  expectSameTexels(*first, *third);
}

// A file of format version 1 (FNV checksum), intact by its own rules, is a
// miss under version 2 (XXH3), never an error, and is rewritten.
TEST_F(BakeCacheTest, FormatVersionOneFileIsAMiss) {
  const auto first = bake(scene());
  const fs::path file = bakeCacheFile(first->cacheKey, options_);
  std::vector<std::uint8_t> bytes(fs::file_size(file));
  std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  const std::size_t checksumAt = bytes.size() - 8;
  for (int i = 0; i < 4; ++i) bytes[8 + std::size_t(i)] = i == 0 ? 1 : 0;  // the version, after the magic
  const std::uint64_t fnv = fnv1aOverWords(bytes, checksumAt);
  for (int i = 0; i < 8; ++i) bytes[checksumAt + std::size_t(i)] = std::uint8_t(fnv >> (8 * i));
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));

  std::shared_ptr<const lighting::BakedLighting> again;
  ASSERT_NO_THROW(again = bake(scene()));
  EXPECT_FALSE(again->fromCache);
  expectSameTexels(*first, *again);
  EXPECT_TRUE(bake(scene())->fromCache);
}

TEST_F(BakeCacheTest, UnwritableCacheFolderStillBakes) {
  // The cache "folder" is a plain file: nothing can be created under it.
  fs::create_directories(dir_);
  std::ofstream(dir_ / "not-a-folder") << "x";
  options_.cacheDirectory = (dir_ / "not-a-folder").string();
  std::shared_ptr<const lighting::BakedLighting> baked;
  ASSERT_NO_THROW(baked = bake(scene()));
  EXPECT_FALSE(baked->fromCache);
  EXPECT_EQ(baked->objects[0].lightmap.resolution, 8);
  ASSERT_NO_THROW(baked = bake(scene()));
  EXPECT_FALSE(baked->fromCache);
}

TEST(BakeCacheFolder, OptionThenEnvironmentThenHome) {
  BakeOptions o;
  o.cacheDirectory = "/somewhere";
  EXPECT_EQ(bakeCacheDirectory(o), fs::path("/somewhere"));
  o.cacheDirectory.clear();
  const char* saved = std::getenv("LIGHTCTS_CACHE_DIR");
  const std::string savedValue = saved ? saved : "";
  ::setenv("LIGHTCTS_CACHE_DIR", "/tmp/lightcts-cache-root", 1);
  EXPECT_EQ(bakeCacheDirectory(o), fs::path("/tmp/lightcts-cache-root/bakes"));
  ::unsetenv("LIGHTCTS_CACHE_DIR");
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const std::string xdgValue = xdg ? xdg : "";
  ::setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(bakeCacheDirectory(o), fs::path("/tmp/xdg/lightcts/bakes"));
  ::unsetenv("XDG_CACHE_HOME");
  if (const char* home = std::getenv("HOME"); home && *home) {
    EXPECT_EQ(bakeCacheDirectory(o), fs::path(home) / ".cache" / "lightcts" / "bakes");
  }
  if (saved) ::setenv("LIGHTCTS_CACHE_DIR", savedValue.c_str(), 1);
  if (xdg) ::setenv("XDG_CACHE_HOME", xdgValue.c_str(), 1);
}

}  // namespace
}  // namespace baking::testing
