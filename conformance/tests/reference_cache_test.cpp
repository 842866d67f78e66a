#include "conformance/reference_cache.h"

#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

namespace conformance {
namespace {

namespace fs = std::filesystem;

reference::ReferenceImages sample() {
  reference::ReferenceImages images;
  images.value = imaging::Image(3, 2, 4);
  images.tolerance = imaging::Image(3, 2, 3);
  for (std::size_t i = 0; i < images.value.pixels.size(); ++i) images.value.pixels[i] = 0.25f * float(i) - 1.0f;
  for (std::size_t i = 0; i < images.tolerance.pixels.size(); ++i) images.tolerance.pixels[i] = 1e-3f * float(i);
  images.lightEvaluations = 123456789012;
  images.maskedPixels = 2;
  images.shadowedPixels = 5;
  images.ambiguousShadowPixels = 1;
  return images;
}

class ReferenceCacheTest : public imaging::testing::ScratchFolderTest {
 protected:
  ReferenceCacheTest() : ScratchFolderTest(false) {}  // the cache creates its folder
  const std::string key_ = referenceCacheKey(std::string(64, 'a'), 0, {});
};

TEST_F(ReferenceCacheTest, SecondAskIsReadBackBitForBit) {
  int renders = 0;
  auto render = [&] {
    ++renders;
    return sample();
  };
  bool hit = true;
  const reference::ReferenceImages first = cachedReference(dir_, key_, render, &hit);
  EXPECT_FALSE(hit);
  const reference::ReferenceImages second = cachedReference(dir_, key_, render, &hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(renders, 1);
  EXPECT_EQ(second.value.pixels, first.value.pixels);
  EXPECT_EQ(second.value.channels, 4);
  EXPECT_EQ(second.tolerance.pixels, first.tolerance.pixels);
  EXPECT_EQ(second.lightEvaluations, 123456789012);
  EXPECT_EQ(second.maskedPixels, 2);
  EXPECT_EQ(second.shadowedPixels, 5);
  EXPECT_EQ(second.ambiguousShadowPixels, 1);
  EXPECT_TRUE(second.shadowInterval.pixels.empty());
}

TEST_F(ReferenceCacheTest, DamagedFileIsAMiss) {
  int renders = 0;
  auto render = [&] {
    ++renders;
    return sample();
  };
  cachedReference(dir_, key_, render);
  const fs::path file = dir_ / (key_ + ".ref");
  ASSERT_TRUE(fs::exists(file));
  {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);
    f.put('\x7f');  // one texel's byte: the checksum no longer matches
  }
  bool hit = true;
  const reference::ReferenceImages again = cachedReference(dir_, key_, render, &hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(renders, 2);
  EXPECT_EQ(again.value.pixels, sample().value.pixels);
  fs::resize_file(file, 40);  // cut short
  cachedReference(dir_, key_, render, &hit);
  EXPECT_FALSE(hit);
}

TEST_F(ReferenceCacheTest, KeyChangesWithEveryInput) {
  const std::string digest(64, 'a');
  reference::ReferenceOptions ideal;
  ideal.ideal = true;
  reference::ReferenceOptions realtime;
  realtime.bakedLightsRealtime = true;
  reference::ReferenceOptions eightBits;
  eightBits.filterWeightPrecision = 1.0 / 256;
  reference::ReferenceOptions intervals;
  intervals.keepShadowIntervals = true;
  const std::vector<std::string> keys = {
      key_, referenceCacheKey(std::string(64, 'b'), 0, {}), referenceCacheKey(digest, 1, {}),
      referenceCacheKey(digest, 0, ideal), referenceCacheKey(digest, 0, realtime),
      referenceCacheKey(digest, 0, eightBits), referenceCacheKey(digest, 0, intervals)};
  for (std::size_t i = 0; i < keys.size(); ++i)
    for (std::size_t j = i + 1; j < keys.size(); ++j) EXPECT_NE(keys[i], keys[j]) << i << " " << j;
  reference::ReferenceOptions threads;
  threads.threads = 3;  // the thread count changes nothing the reference holds
  EXPECT_EQ(referenceCacheKey(digest, 0, threads), key_);
}

TEST_F(ReferenceCacheTest, ExtraImagesAreNeverCached) {
  reference::ReferenceOptions exact;
  exact.keepExactValues = true;
  reference::ReferenceOptions terms;
  terms.keepToleranceTerms = true;
  EXPECT_FALSE(cacheable(exact));
  EXPECT_FALSE(cacheable(terms));
  EXPECT_TRUE(cacheable({}));
}

// Four workers asking for one key at once: one renders, three wait on its
// lock and read its file.
TEST_F(ReferenceCacheTest, ConcurrentAsksRenderOnce) {
  std::atomic<int> renders = 0;
  auto render = [&] {
    ++renders;
    volatile double sink = 0;
    for (int i = 0; i < 2000000; ++i) sink = sink + 1e-9 * i;  // long enough for the others to arrive
    return sample();
  };
  std::vector<std::jthread> workers;
  for (int w = 0; w < 4; ++w) workers.emplace_back([&] { cachedReference(dir_, key_, render); });
  workers.clear();
  EXPECT_EQ(renders.load(), 1);
}

TEST_F(ReferenceCacheTest, NoFolderMeansNoCache) {
  int renders = 0;
  auto render = [&] {
    ++renders;
    return sample();
  };
  cachedReference({}, key_, render);
  cachedReference({}, key_, render);
  EXPECT_EQ(renders, 2);
}

}  // namespace
}  // namespace conformance
