// Reporting a Comparison (image_comparison.h): a short text for people, JSON
// for tools, and the evidence folder every failure leaves (SPEC 7).
#pragma once

#include "comparison/image_comparison.h"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <string_view>

namespace comparison {

// First line: "VERDICT NAME: N failing of M compared pixels (K masked), max
// error E, tightness T"; then, where they apply, the non-finite count, the
// failing-pixel allowance and tolerance scale, whether an expect_fail scene's
// mismatch was detected, and one line per worst pixel with its allowed bounds.
// testName names the case, for example "attenuation.point-d-zero.vulkan".
void printComparison(std::ostream& out, const Comparison& comparison, std::string_view testName);

// Every field of the Comparison except the error mask (an image), keys in
// snake_case like the scene files. Non-finite numbers are written as the
// strings "inf", "-inf" and "nan", since JSON has no such numbers.
nlohmann::ordered_json comparisonJson(const Comparison& comparison, std::string_view testName);

// Creates `dir` and writes result.exr, reference.exr (RGB value, A mask),
// tolerance.exr, result.png and reference.png (tone-mapped previews),
// error-mask.png (the mask as 8-bit 0 / 64 / 255), the viewer (viewer.html
// and viewer-data.js, evidence_viewer.h) and, last, summary.json
// (comparisonJson): its presence means the evidence is complete. Every file is
// written to a hidden temporary name and renamed into place. Throws
// std::runtime_error (imaging::ImageFileError, std::filesystem::filesystem_error)
// when a file cannot be written.
//
// SPEC 3.9's shadow maps, when given: shadow-map-<v>-backend.exr/.png (the
// backend's stored depth, read back) and shadow-map-<v>-reference.exr/.png
// (RGB: the reference's depth, then the lowest and highest depth a correct
// pass may store), one per view in lighting::shadowPassViews order.
struct ShadowMapEvidence {
  std::vector<imaging::Image> backend;
  std::vector<imaging::Image> reference;
};
void writeEvidence(const std::string& dir, const Comparison& comparison, const imaging::Image& result,
                   const reference::ReferenceImages& reference, std::string_view testName,
                   const ShadowMapEvidence* shadowMaps = nullptr);

}  // namespace comparison
