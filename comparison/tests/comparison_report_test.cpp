// The text report, the JSON, and the evidence folder, on the same hand-built
// 4x3 images as image_comparison_test.cpp.
#include "comparison/comparison_report.h"
#include "comparison/tests/comparison_fixtures.h"
#include "imaging/image_files.h"
#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace comparison {
namespace {

namespace fs = std::filesystem;
using namespace comparison::testing;

// One pixel off by 0.5 in red at (2, 1), one masked pixel at (0, 0).
Images onePixelOff() {
  Images images = uniform(4, 3);
  images.result.at(2, 1, 0) = 1.0f;
  mask(images, 0, 0);
  return images;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// A fresh folder per test, removed afterwards.
// The evidence writer creates its folder: it does not exist when a test starts.
class EvidenceFolder : public imaging::testing::ScratchFolderTest {
 protected:
  EvidenceFolder() : ScratchFolderTest(false) {}
};

TEST(PrintComparison, FirstLineAndWorstPixels) {
  const Images images = onePixelOff();
  std::ostringstream out;
  printComparison(out, compareImages(images.result, images.reference, {}), "attenuation.point-d-zero.vulkan");
  const std::vector<std::string> text = lines(out.str());
  ASSERT_EQ(text.size(), 2u) << out.str();
  EXPECT_EQ(text[0],
            "Fail attenuation.point-d-zero.vulkan: 1 failing of 11 compared pixels (1 masked), max error 0.5, "
            "tightness 2");
  EXPECT_EQ(text[1],
            "  (2, 1) result (1, 0.5, 0.5) reference (0.5, 0.5, 0.5) allowed [0.25, 0.75] [0.25, 0.75] "
            "[0.25, 0.75] excess 0.25");
}

TEST(PrintComparison, ShowsFloatDifferences) {
  Images images = uniform(1, 1);
  images.reference.tolerance.at(0, 0, 0) = 0;
  images.result.at(0, 0, 0) = 0.5f + 0x1p-24f;
  std::ostringstream out;
  printComparison(out, compareImages(images.result, images.reference, {}), "t");
  EXPECT_NE(out.str().find("result (0.50000006, 0.5, 0.5)"), std::string::npos) << out.str();
}

TEST(PrintComparison, SaysWhetherAnExpectedMismatchWasDetected) {
  lighting::Expectation expect;
  expect.expectFail = true;
  const Images off = onePixelOff();
  std::ostringstream detected;
  printComparison(detected, compareImages(off.result, off.reference, expect), "t");
  EXPECT_EQ(lines(detected.str())[0].rfind("Pass t: 1 failing", 0), 0u) << detected.str();
  EXPECT_NE(detected.str().find("expected mismatch was detected"), std::string::npos) << detected.str();

  const Images equal = uniform(4, 3);
  std::ostringstream undetected;
  printComparison(undetected, compareImages(equal.result, equal.reference, expect), "t");
  EXPECT_EQ(lines(undetected.str())[0].rfind("Fail t: 0 failing", 0), 0u) << undetected.str();
  EXPECT_NE(undetected.str().find("UNDETECTED"), std::string::npos) << undetected.str();
}

TEST(PrintComparison, ExpectFailWithNonFiniteValues) {
  Images images = uniform(4, 3);
  images.result.at(0, 1, 0) = std::numeric_limits<float>::infinity();
  lighting::Expectation expect;
  expect.expectFail = true;
  std::ostringstream out;
  printComparison(out, compareImages(images.result, images.reference, expect), "t");
  const std::vector<std::string> text = lines(out.str());
  ASSERT_EQ(text.size(), 4u) << out.str();
  EXPECT_EQ(text[0].rfind("Fail t: 1 failing", 0), 0u) << out.str();
  EXPECT_EQ(text[1], "  1 non-finite pixels (NaN or infinity in the result always fail)");
  EXPECT_NE(text[2].find("never the expected mismatch"), std::string::npos) << out.str();
  EXPECT_EQ(text[3],
            "  (0, 1) result (inf, 0.5, 0.5) reference (0.5, 0.5, 0.5) allowed [0.25, 0.75] [0.25, 0.75] "
            "[0.25, 0.75] excess inf non-finite");
}

TEST(PrintComparison, CountsFailingPixelsNotListed) {
  Images images = uniform(4, 3);
  for (int x = 0; x < 4; ++x) images.result.at(x, 0, 0) = 1.0f;
  std::ostringstream out;
  printComparison(out, compareImages(images.result, images.reference, {}, 2), "t");
  const std::vector<std::string> text = lines(out.str());
  ASSERT_EQ(text.size(), 4u) << out.str();
  EXPECT_EQ(text[3], "  and 2 more failing pixels");
}

TEST(ComparisonJson, FieldsAndVerdict) {
  const Images images = onePixelOff();
  const nlohmann::ordered_json json = comparisonJson(compareImages(images.result, images.reference, {}), "a.b.c");
  EXPECT_EQ(json["test"], "a.b.c");
  EXPECT_EQ(json["verdict"], "Fail");
  EXPECT_EQ(json["comparison_passed"], false);
  EXPECT_EQ(json["expect_fail"], false);
  EXPECT_EQ(json["width"], 4);
  EXPECT_EQ(json["height"], 3);
  EXPECT_EQ(json["compared_pixels"], 11);
  EXPECT_EQ(json["masked_pixels"], 1);
  EXPECT_EQ(json["failing_pixels"], 1);
  EXPECT_EQ(json["non_finite_pixels"], 0);
  EXPECT_EQ(json["max_failing_pixels"], 0);
  EXPECT_EQ(json["tolerance_scale"], 1.0);
  EXPECT_EQ(json["max_abs_error"], 0.5);
  EXPECT_EQ(json["max_error_over_tolerance"], 2.0);
  EXPECT_TRUE(json["rmse"].is_number());
  ASSERT_EQ(json["worst"].size(), 1u);
  const auto& p = json["worst"][0];
  EXPECT_EQ(p["x"], 2);
  EXPECT_EQ(p["y"], 1);
  EXPECT_EQ(p["result"], nlohmann::ordered_json::array({1.0, 0.5, 0.5}));
  EXPECT_EQ(p["reference"], nlohmann::ordered_json::array({0.5, 0.5, 0.5}));
  EXPECT_EQ(p["tolerance"], nlohmann::ordered_json::array({0.25, 0.25, 0.25}));
  EXPECT_EQ(p["allowed"][0], nlohmann::ordered_json::array({0.25, 0.75}));
  EXPECT_EQ(p["excess"], 0.25);
  EXPECT_EQ(p["non_finite"], false);
}

TEST(ComparisonJson, NonFiniteNumbersBecomeStrings) {
  Images images = uniform(2, 1);
  images.result.at(0, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  images.result.at(0, 0, 1) = -std::numeric_limits<float>::infinity();
  images.reference.tolerance.at(1, 0, 2) = 0;
  images.result.at(1, 0, 2) = 0.75f;  // over a zero tolerance: tightness +inf
  const nlohmann::json parsed =
      nlohmann::json::parse(comparisonJson(compareImages(images.result, images.reference, {}), "t").dump());
  EXPECT_EQ(parsed["max_error_over_tolerance"], "inf");
  ASSERT_EQ(parsed["worst"].size(), 2u);
  EXPECT_EQ(parsed["worst"][0]["excess"], "inf");
  EXPECT_EQ(parsed["worst"][0]["result"][0], "nan");
  EXPECT_EQ(parsed["worst"][0]["result"][1], "-inf");
  EXPECT_EQ(parsed["worst"][0]["non_finite"], true);
  EXPECT_EQ(parsed["worst"][1]["excess"], 0.25);
}

// RFC 4648 base64, decoded here by hand: the viewer's data must read back
// as the very floats of the images, checked by a path other than the writer's.
std::vector<float> decodeFloats(const std::string& base64) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> bytes;
  unsigned bits = 0, held = 0;
  for (const char c : base64) {
    if (c == '=') break;
    bits = (bits << 6) | unsigned(alphabet.find(c));
    held += 6;
    if (held >= 8) {
      held -= 8;
      bytes.push_back(std::uint8_t((bits >> held) & 0xff));
    }
  }
  std::vector<float> values(bytes.size() / 4);
  std::memcpy(values.data(), bytes.data(), values.size() * 4);  // little-endian, as the format says
  return values;
}

TEST_F(EvidenceFolder, ViewerDataHoldsTheImagesFloatsTopRowFirst) {
  Images images = onePixelOff();
  images.result.at(3, 2, 1) = std::numeric_limits<float>::quiet_NaN();  // last pixel's green
  images.reference.tolerance.at(1, 0, 2) = 0.1f;                          // not a binary fraction
  const Comparison c = compareImages(images.result, images.reference, {});
  writeEvidence(dir_.string(), c, images.result, images.reference, "a.b.c");

  std::ifstream in(dir_ / "viewer-data.js");
  std::stringstream text;
  text << in.rdbuf();
  const std::string prefix = "window.LIGHTCTS_EVIDENCE = ";
  ASSERT_EQ(text.str().rfind(prefix, 0), 0u) << text.str().substr(0, 40);
  std::string body = text.str().substr(prefix.size());
  body = body.substr(0, body.rfind(';'));
  const nlohmann::json data = nlohmann::json::parse(body);
  EXPECT_EQ(data["width"], 4);
  EXPECT_EQ(data["height"], 3);
  EXPECT_EQ(data["test"], "a.b.c");
  EXPECT_EQ(data["summary"]["failing_pixels"], 2);  // the red 1.0 and the NaN

  const std::vector<float> result = decodeFloats(data["images"]["result"]["data"]);
  ASSERT_EQ(result.size(), 4u * 3u * 3u);
  EXPECT_EQ(result[(1 * 4 + 2) * 3 + 0], 1.0f);  // (2, 1) red, row 1 from the top
  EXPECT_EQ(result[(0 * 4 + 0) * 3 + 0], kValue);
  EXPECT_TRUE(std::isnan(result[(2 * 4 + 3) * 3 + 1]));
  const std::vector<float> tolerance = decodeFloats(data["images"]["tolerance"]["data"]);
  EXPECT_EQ(tolerance[(0 * 4 + 1) * 3 + 2], 0.1f);
  const std::vector<float> maskValues = decodeFloats(data["images"]["mask"]["data"]);
  ASSERT_EQ(maskValues.size(), 12u);
  EXPECT_EQ(maskValues[0], 0.0f);  // (0, 0) is masked
  EXPECT_EQ(maskValues[1], 1.0f);
  EXPECT_EQ(data["images"]["error"]["channels"], 3);
  const std::vector<float> error = decodeFloats(data["images"]["error"]["data"]);
  EXPECT_EQ(error[(1 * 4 + 2) * 3 + 0], 1.0f);  // failing: red
  EXPECT_EQ(error[(1 * 4 + 2) * 3 + 1], 0.0f);

  // The page is the one the build carries, byte for byte the source's, and
  // loads the data beside it.
  std::ifstream page(dir_ / "viewer.html", std::ios::binary);
  std::stringstream html;
  html << page.rdbuf();
  std::ifstream source(LIGHTCTS_SOURCE_DIR "/reports/viewer/evidence_viewer.html", std::ios::binary);
  ASSERT_TRUE(source) << "reports/viewer/evidence_viewer.html";
  std::stringstream sourceText;
  sourceText << source.rdbuf();
  EXPECT_EQ(html.str(), sourceText.str());
  EXPECT_NE(html.str().find("viewer-data.js"), std::string::npos);
}

TEST_F(EvidenceFolder, WritesEveryFileAndSummaryLast) {
  const Images images = onePixelOff();
  const Comparison c = compareImages(images.result, images.reference, {});
  writeEvidence(dir_.string(), c, images.result, images.reference, "a.b.c");

  for (const char* name : {"result.exr", "reference.exr", "tolerance.exr", "result.png", "reference.png",
                           "error-mask.png", "viewer.html", "viewer-data.js", "summary.json"})
    EXPECT_TRUE(fs::is_regular_file(dir_ / name)) << name;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    ++files;
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos) << entry.path();
  }
  EXPECT_EQ(files, 9);

  std::ifstream summary(dir_ / "summary.json");
  const nlohmann::json json = nlohmann::json::parse(summary);
  EXPECT_EQ(json["failing_pixels"], 1);
  EXPECT_EQ(json["verdict"], "Fail");
  EXPECT_EQ(json["test"], "a.b.c");

  const imaging::Image reference = imaging::readExr((dir_ / "reference.exr").string());
  EXPECT_EQ(reference.channels, 4);
  EXPECT_EQ(reference.pixels, images.reference.value.pixels);
}

// SPEC 3.9: the backend's and the reference's shadow maps, each view as EXR
// with its values and a PNG for people, beside the rest.
TEST_F(EvidenceFolder, WritesTheShadowMapsOfBothSides) {
  const Images images = onePixelOff();
  ShadowMapEvidence maps;
  imaging::Image backend(2, 2, 1), reference(2, 2, 3);
  backend.at(1, 0, 0) = 0.5f;
  reference.at(1, 0, 2) = 0.75f;
  maps.backend = {backend, backend};
  maps.reference = {reference, reference};
  writeEvidence(dir_.string(), compareImages(images.result, images.reference, {}), images.result, images.reference,
                "t", &maps);
  for (const char* name : {"shadow-map-0-backend.exr", "shadow-map-0-backend.png", "shadow-map-1-backend.exr",
                           "shadow-map-0-reference.exr", "shadow-map-1-reference.png", "summary.json"})
    EXPECT_TRUE(fs::is_regular_file(dir_ / name)) << name;
  const imaging::Image back = imaging::readExr((dir_ / "shadow-map-1-backend.exr").string());
  EXPECT_EQ(back.channels, 1);
  EXPECT_EQ(back.at(1, 0, 0), 0.5f);
  EXPECT_EQ(imaging::readExr((dir_ / "shadow-map-0-reference.exr").string()).at(1, 0, 2), 0.75f);
}

TEST_F(EvidenceFolder, ErrorMaskHoldsExactLevels) {
  Images images = onePixelOff();
  images.result.at(3, 2, 0) = std::numeric_limits<float>::quiet_NaN();
  writeEvidence(dir_.string(), compareImages(images.result, images.reference, {}), images.result, images.reference,
                "t");

  const imaging::Image8 mask = imaging::readImage8((dir_ / "error-mask.png").string());
  ASSERT_EQ(mask.width, 4);
  ASSERT_EQ(mask.height, 3);
  ASSERT_EQ(mask.channels, 3);
  const std::vector<std::uint8_t>& bytes = mask.levels;
  const auto rgb = [&](int x, int y) {
    const std::size_t i = (std::size_t(y) * 4 + x) * 3;
    return std::vector<int>{bytes[i], bytes[i + 1], bytes[i + 2]};
  };
  EXPECT_EQ(rgb(0, 0), (std::vector<int>{64, 64, 64}));     // masked
  EXPECT_EQ(rgb(2, 1), (std::vector<int>{255, 0, 0}));      // failing
  EXPECT_EQ(rgb(3, 2), (std::vector<int>{255, 0, 255}));    // non-finite
  EXPECT_EQ(rgb(1, 1), (std::vector<int>{0, 0, 0}));        // passing
}

TEST_F(EvidenceFolder, ReplacesAnEarlierRun) {
  Images images = onePixelOff();
  writeEvidence(dir_.string(), compareImages(images.result, images.reference, {}), images.result, images.reference,
                "t");
  images.result.at(1, 1, 1) = 0.0f;
  writeEvidence(dir_.string(), compareImages(images.result, images.reference, {}), images.result, images.reference,
                "t");
  std::ifstream summary(dir_ / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(summary)["failing_pixels"], 2);
}

}  // namespace
}  // namespace comparison
