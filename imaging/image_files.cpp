#include "imaging/image_files.h"

#include "imaging/atomic_file.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace imaging {
namespace {

namespace fs = std::filesystem;

// Writes through OIIO to a temporary beside `path` (atomic_file.h), renamed
// over `path` when complete. OIIO picks the format from the extension, which
// the temporary name keeps.
void writeAtomically(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc format,
                     const void* pixels) {
  try {
    writeThroughTemporary(path, [&](const fs::path& temporary) {
      auto out = OIIO::ImageOutput::create(temporary.string());
      if (!out) throw ImageFileError("cannot write " + path + ": " + OIIO::geterror());
      if (!out->open(temporary.string(), spec) || !out->write_image(format, pixels) || !out->close())
        throw ImageFileError("cannot write " + path + ": " + out->geterror());
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

}  // namespace

void writeExr(const std::string& path, const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, image.pixels.data());
}

Image readExr(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw ImageFileError("cannot read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image image(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw ImageFileError("cannot read " + path + ": " + in->geterror());
  return image;
}

Image readDataChannel(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw ImageFileError("cannot read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int channel = spec.alpha_channel >= 0 ? spec.alpha_channel : 0;
  Image image(spec.width, spec.height, 1);
  // Read as stored: OIIO converts UNORM levels to floats n / 255 and applies
  // no colour transform unless asked to.
  if (!in->read_image(0, 0, channel, channel + 1, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw ImageFileError("cannot read " + path + ": " + in->geterror());
  return image;
}

void writePng8(const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& bytes) {
  if (bytes.size() != std::size_t(width) * std::size_t(height) * std::size_t(channels))
    throw ImageFileError("cannot write " + path + ": " + std::to_string(bytes.size()) + " bytes for a " +
                         std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(channels) +
                         " image");
  const OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
  writeAtomically(path, spec, OIIO::TypeDesc::UINT8, bytes.data());
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
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  writeAtomically(path, spec, OIIO::TypeDesc::UINT8, bytes.data());
}

}  // namespace imaging
