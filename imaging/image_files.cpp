#include "imaging/image_files.h"

#include "imaging/atomic_file.h"
#include "imaging/image_codec_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace imaging {
namespace {

namespace fs = std::filesystem;

// Writes through the image module to a temporary beside `path`
// (atomic_file.h), renamed over `path` when complete. The module picks the
// format from the extension, which the temporary name keeps.
void writeAtomically(const std::string& path, int width, int height, int channels, SampleType type,
                     const void* pixels) {
  ImageCodec& codec = imageCodec();  // loaded before any temporary exists
  try {
    writeThroughTemporary(path, [&](const fs::path& temporary) {
      const std::string error = codec.write(temporary.string(), width, height, channels, type, pixels);
      if (!error.empty()) throw ImageFileError("cannot write " + path + ": " + error);
    });
  } catch (const ImageFileError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw ImageFileError(e.what());  // the rename failed: callers catch image errors as ImageFileError
  }
}

double toneMapToSrgb(double linear) {
  if (!std::isfinite(linear)) return linear > 0 ? 1.0 : 0.0;  // NaN shows black, +inf white
  const double x = std::max(linear, 0.0);
  const double mapped = x / (1.0 + x);
  return mapped <= 0.0031308 ? 12.92 * mapped : 1.055 * std::pow(mapped, 1.0 / 2.4) - 0.055;
}

Image readFloat(const std::string& path, ChannelChoice channels) {
  Image image;
  const std::string error = imageCodec().readFloat(path, channels, image);
  if (!error.empty()) throw ImageFileError("cannot read " + path + ": " + error);
  return image;
}

}  // namespace

void writeExr(const std::string& path, const Image& image) {
  writeAtomically(path, image.width, image.height, image.channels, SampleType::Float32, image.pixels.data());
}

Image readExr(const std::string& path) { return readFloat(path, ChannelChoice::All); }

// Read as stored: the module converts UNORM levels to floats n / 255 and
// applies no colour transform.
Image readDataChannel(const std::string& path) { return readFloat(path, ChannelChoice::AlphaOrFirst); }

Image8 readImage8(const std::string& path) {
  Image8 image;
  const std::string error = imageCodec().readUInt8(path, image);
  if (!error.empty()) throw ImageFileError("cannot read " + path + ": " + error);
  return image;
}

void writePng8(const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() != std::size_t(width) * std::size_t(height) * std::size_t(channels))
    throw ImageFileError("cannot write " + path + ": " + std::to_string(bytes.size()) + " bytes for a " +
                         std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(channels) +
                         " image");
  writeAtomically(path, width, height, channels, SampleType::UInt8, bytes.data());
}

void writePngPreview(const std::string& path, const Image& image) {
  const int channels = std::min(image.channels, 3);
  std::vector<std::uint8_t> bytes(std::size_t(image.width) * image.height * 3, 0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = toneMapToSrgb(image.at(x, y, std::min(c, channels - 1)));
        bytes[(std::size_t(y) * image.width + x) * 3 + c] = std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
      }
  writeAtomically(path, image.width, image.height, 3, SampleType::UInt8, bytes.data());
}

}  // namespace imaging
