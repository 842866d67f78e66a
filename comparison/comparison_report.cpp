#include "comparison/comparison_report.h"

#include "comparison/evidence_viewer.h"
#include "imaging/atomic_file.h"
#include "imaging/image_files.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace comparison {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Nine significant digits tell any two floats apart.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// Appending rather than `"(" + ...`, which trips GCC 12's false -Wrestrict
// warning (GCC bug 105329) at -O3.
std::string triple(const float (&values)[3]) {
  std::string text = "(";
  text += number(values[0]) + ", " + number(values[1]) + ", " + number(values[2]) + ")";
  return text;
}

double allowedLow(const PixelReport& p, int c, double scale) { return double(p.reference[c]) - p.tolerance[c] * scale; }
double allowedHigh(const PixelReport& p, int c, double scale) { return double(p.reference[c]) + p.tolerance[c] * scale; }

// nlohmann writes NaN and infinity as null, which would read back as "no value".
Json jsonNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

Json jsonTriple(const float (&values)[3]) {
  return Json::array({jsonNumber(values[0]), jsonNumber(values[1]), jsonNumber(values[2])});
}

// The mask is data, not light: written as exact 8-bit levels rather than
// through writePngPreview's tone mapping.
void writeErrorMask(const fs::path& target, const imaging::Image& mask) {
  std::vector<std::uint8_t> bytes(mask.pixels.size());
  std::transform(mask.pixels.begin(), mask.pixels.end(), bytes.begin(),
                 [](float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); });
  imaging::writePng8(target.string(), mask.width, mask.height, mask.channels, bytes);
}

// A shadow map's depth (channel 0) as grey levels for people: the stored
// depths below the clear value 1 stretched from black (the nearest) to light
// grey, 1 (nothing there) white. A perspective map's depths crowd near 1, so
// an unstretched picture would be white all over; the EXR keeps the values.
void writeDepthPng(const std::string& target, const imaging::Image& map) {
  float nearest = 1, farthest = 0;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      if (const float d = map.at(x, y, 0); d < 1) {
        nearest = std::min(nearest, d);
        farthest = std::max(farthest, d);
      }
  const double span = farthest > nearest ? double(farthest) - nearest : 1.0;
  std::vector<std::uint8_t> bytes(std::size_t(map.width) * map.height, 255);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      if (const float d = map.at(x, y, 0); d < 1)
        bytes[std::size_t(y) * map.width + x] =
            std::uint8_t(std::lround(std::clamp((d - nearest) / span, 0.0, 1.0) * 200.0));
  imaging::writePng8(target, map.width, map.height, 1, bytes);
}

}  // namespace

void printComparison(std::ostream& out, const Comparison& comparison, std::string_view testName) {
  out << verdictName(comparison.verdict) << ' ' << testName << ": " << comparison.failingPixels << " failing of "
      << comparison.comparedPixels << " compared pixels (" << comparison.maskedPixels << " masked), max error "
      << number(comparison.maxAbsError) << ", tightness " << number(comparison.maxErrorOverTolerance) << '\n';
  if (comparison.verdict == Verdict::QualityWarning)
    out << "  QualityWarning: " << comparison.qualityWarning << " (SPEC 7: a comparison must be able to fail)\n";
  if (comparison.nonFinitePixels > 0)
    out << "  " << comparison.nonFinitePixels << " non-finite pixels (NaN or infinity in the result always fail)\n";
  if (comparison.maxFailingPixels > 0) out << "  up to " << comparison.maxFailingPixels << " failing pixels allowed\n";
  if (comparison.toleranceScale != 1) out << "  tolerances scaled by " << number(comparison.toleranceScale) << '\n';
  if (comparison.shadowedPixels > 0)
    out << "  " << comparison.ambiguousShadowPixels << " of " << comparison.shadowedPixels
        << " shadowed pixels have an admissible shadow interval wider than 0.01"
        << (comparison.defectiveScene ? ": more than 5%, a DEFECTIVE SCENE (SPEC 3.9), it fails whatever the pixels say"
                                      : "")
        << '\n';
  if (comparison.expectFail) {
    if (comparison.comparisonPassed)
      out << "  expect_fail: the expected mismatch went UNDETECTED (the comparison passed)\n";
    else if (comparison.nonFinitePixels > 0)
      out << "  expect_fail: the comparison failed, but non-finite values are never the expected mismatch\n";
    else
      out << "  expect_fail: the expected mismatch was detected\n";
  }

  for (const PixelReport& p : comparison.worst) {
    out << "  (" << p.x << ", " << p.y << ") result " << triple(p.result) << " reference " << triple(p.reference)
        << " allowed";
    for (int c = 0; c < 3; ++c)
      out << " [" << number(allowedLow(p, c, comparison.toleranceScale)) << ", "
          << number(allowedHigh(p, c, comparison.toleranceScale)) << ']';
    out << " excess " << number(p.excess) << (p.nonFinite ? " non-finite" : "");
    if (p.shadowed) out << " shadow s in [" << number(p.shadowLo) << ", " << number(p.shadowHi) << ']';
    out << '\n';
  }
  const long long unlisted = comparison.failingPixels - static_cast<long long>(comparison.worst.size());
  if (!comparison.worst.empty() && unlisted > 0) out << "  and " << unlisted << " more failing pixels\n";
}

Json comparisonJson(const Comparison& comparison, std::string_view testName) {
  Json worst = Json::array();
  for (const PixelReport& p : comparison.worst) {
    Json allowed = Json::array();
    for (int c = 0; c < 3; ++c)
      allowed.push_back(Json::array({jsonNumber(allowedLow(p, c, comparison.toleranceScale)),
                                     jsonNumber(allowedHigh(p, c, comparison.toleranceScale))}));
    worst.push_back(Json{{"x", p.x},
                         {"y", p.y},
                         {"result", jsonTriple(p.result)},
                         {"reference", jsonTriple(p.reference)},
                         {"tolerance", jsonTriple(p.tolerance)},
                         {"allowed", allowed},
                         {"excess", jsonNumber(p.excess)},
                         {"non_finite", p.nonFinite},
                         {"shadow_interval", p.shadowed ? Json::array({jsonNumber(p.shadowLo), jsonNumber(p.shadowHi)})
                                                        : Json(nullptr)}});
  }
  return Json{{"test", testName},
              {"verdict", verdictName(comparison.verdict)},
              {"comparison_passed", comparison.comparisonPassed},
              {"expect_fail", comparison.expectFail},
              {"width", comparison.width},
              {"height", comparison.height},
              {"compared_pixels", comparison.comparedPixels},
              {"masked_pixels", comparison.maskedPixels},
              {"lit_compared_pixels", comparison.litComparedPixels},
              {"quality_warning", comparison.qualityWarning},
              {"failing_pixels", comparison.failingPixels},
              {"non_finite_pixels", comparison.nonFinitePixels},
              {"max_failing_pixels", comparison.maxFailingPixels},
              {"tolerance_scale", jsonNumber(comparison.toleranceScale)},
              {"max_abs_error", jsonNumber(comparison.maxAbsError)},
              {"max_error_over_tolerance", jsonNumber(comparison.maxErrorOverTolerance)},
              {"rmse", jsonNumber(comparison.rmse)},
              {"shadowed_pixels", comparison.shadowedPixels},
              {"ambiguous_shadow_pixels", comparison.ambiguousShadowPixels},
              {"defective_scene", comparison.defectiveScene},
              {"worst", worst}};
}

void writeEvidence(const std::string& dir, const Comparison& comparison, const imaging::Image& result,
                   const reference::ReferenceImages& reference, std::string_view testName,
                   const ShadowMapEvidence* shadowMaps) {
  const fs::path folder(dir);
  fs::create_directories(folder);
  // A summary from an earlier run would vouch for the files about to be
  // replaced if this run stopped half way.
  fs::remove(folder / "summary.json");
  const auto path = [&](const char* name) { return (folder / name).string(); };
  imaging::writeExr(path("result.exr"), result);
  imaging::writeExr(path("reference.exr"), reference.value);
  imaging::writeExr(path("tolerance.exr"), reference.tolerance);
  imaging::writePngPreview(path("result.png"), result);
  imaging::writePngPreview(path("reference.png"), reference.value);
  writeErrorMask(folder / "error-mask.png", comparison.errorMask);
  // SPEC 3.9: the backend's maps as read back, and the reference's (depth,
  // then the admissible [lo, hi] each texel allows), one pair per view.
  if (shadowMaps) {
    for (std::size_t v = 0; v < shadowMaps->backend.size(); ++v) {
      const std::string stem = "shadow-map-" + std::to_string(v);
      imaging::writeExr(path((stem + "-backend.exr").c_str()), shadowMaps->backend[v]);
      writeDepthPng(path((stem + "-backend.png").c_str()), shadowMaps->backend[v]);
    }
    for (std::size_t v = 0; v < shadowMaps->reference.size(); ++v) {
      const std::string stem = "shadow-map-" + std::to_string(v);
      imaging::writeExr(path((stem + "-reference.exr").c_str()), shadowMaps->reference[v]);
      writeDepthPng(path((stem + "-reference.png").c_str()), shadowMaps->reference[v]);
    }
  }
  const Json summary = comparisonJson(comparison, testName);
  writeEvidenceViewer(folder, comparison, result, reference, summary);
  imaging::writeFileAtomically(folder / "summary.json", summary.dump(2) + "\n");
}

}  // namespace comparison
