#include "comparison/evidence_viewer.h"

#include "comparison/evidence_viewer_page.h"  // generated: the page's text (cmake/embedded_text_header.cmake)
#include "imaging/atomic_file.h"
#include "imaging/image_codec_loader.h"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace comparison {
namespace {

static_assert(std::endian::native == std::endian::little, "viewer-data.js holds little-endian float32");

// `channels` of `image` (from channel `first`), as base64 of float32: the
// browser decodes it into a Float32Array, bit for bit what the EXR holds.
std::string base64Channels(const imaging::Image& image, int first, int channels) {
  if (image.channels < first + channels)
    throw std::invalid_argument("evidence viewer: an image has " + std::to_string(image.channels) + " channels, " +
                                std::to_string(first + channels) + " needed");
  std::vector<float> values;
  values.reserve(std::size_t(image.width) * image.height * channels);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < channels; ++c) values.push_back(image.at(x, y, first + c));
  std::string bytes(values.size() * sizeof(float), '\0');
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return imaging::imageCodec().base64(bytes);  // OpenImageIO's encoder, in the image module
}

nlohmann::ordered_json imageJson(const imaging::Image& image, int first, int channels) {
  return {{"channels", channels}, {"data", base64Channels(image, first, channels)}};
}

}  // namespace

std::string evidenceViewerData(const Comparison& comparison, const imaging::Image& result,
                               const reference::ReferenceImages& reference, const nlohmann::ordered_json& summary) {
  const nlohmann::ordered_json data = {
      {"test", summary.value("test", "")},
      {"width", result.width},
      {"height", result.height},
      {"tolerance_scale", comparison.toleranceScale},
      {"images",
       {{"result", imageJson(result, 0, 3)},
        {"reference", imageJson(reference.value, 0, 3)},
        {"tolerance", imageJson(reference.tolerance, 0, 3)},
        {"mask", imageJson(reference.value, 3, 1)},
        {"error", imageJson(comparison.errorMask, 0, 3)}}},
      {"summary", summary}};
  // A script, not JSON to fetch: Chromium refuses fetch() from file://.
  return "window.LIGHTCTS_EVIDENCE = " + data.dump() + ";\n";
}

void writeEvidenceViewer(const std::filesystem::path& folder, const Comparison& comparison,
                         const imaging::Image& result, const reference::ReferenceImages& reference,
                         const nlohmann::ordered_json& summary) {
  imaging::writeFileAtomically(folder / "viewer-data.js", evidenceViewerData(comparison, result, reference, summary));
  imaging::writeFileAtomically(folder / "viewer.html", std::string(kEvidenceViewerPage));
}

}  // namespace comparison
