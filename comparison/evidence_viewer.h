// The evidence viewer (reports/viewer/evidence_viewer.html): one static page
// per evidence folder that switches and swipes between result, reference,
// tolerance and error mask, zooms to single pixels and probes each pixel's
// float values, read from the images themselves, not from the 8-bit
// previews. It needs no network and works from file://: the page is copied
// beside the data (viewer.html) and loads viewer-data.js with a script tag.
#pragma once

#include "comparison/image_comparison.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace comparison {

// viewer-data.js: `window.LIGHTCTS_EVIDENCE = {...}` with the width, height,
// tolerance scale, the summary (comparisonJson) and per image its channel
// count and base64 of its little-endian float32 values, row 0 at the top:
// result (RGB), reference (RGB), tolerance (RGB), mask (1 compared, 0 don't
// care) and error (the error mask's RGB). reports/viewer/README.md has the format.
std::string evidenceViewerData(const Comparison& comparison, const imaging::Image& result,
                               const reference::ReferenceImages& reference, const nlohmann::ordered_json& summary);

// Writes viewer-data.js and viewer.html into `folder` (atomically, each).
void writeEvidenceViewer(const std::filesystem::path& folder, const Comparison& comparison,
                         const imaging::Image& result, const reference::ReferenceImages& reference,
                         const nlohmann::ordered_json& summary);

}  // namespace comparison
