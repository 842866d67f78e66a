// Writing and reading images, through the image module (image_codec.h:
// OpenImageIO, loaded on first use; ImageModuleError when it cannot be). Writes go to a temporary file
// in the same folder and are renamed into place (atomic_file.h), so a failed
// or interrupted write never leaves a half-written image behind.
#pragma once

#include "imaging/image.h"
#include "imaging/image_codec.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace imaging {

class ImageFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Float EXR with the image's channels (3: RGB, 4: RGBA), row 0 at the top.
void writeExr(const std::string& path, const Image& image);
Image readExr(const std::string& path);

// Every channel of a file as its 8-bit levels (PNG's as stored).
Image8 readImage8(const std::string& path);

// One channel of a PNG or EXR as data (SPEC 3.10's cookies): the alpha
// channel when the file has one, else the first; PNG's 8-bit levels n become
// n / 255 exactly as stored (no sRGB decoding), row 0 at the top. Throws
// ImageFileError naming the path for a missing or unreadable file.
Image readDataChannel(const std::string& path);

// 8-bit sRGB PNG for people: linear RGB tone-mapped with x / (1 + x) per
// channel, then encoded with the sRGB transfer function. Alpha is dropped.
void writePngPreview(const std::string& path, const Image& image);

// An exact 8-bit PNG of data, not light (error masks, overlap maps): `bytes`
// holds width * height * channels levels, row 0 at the top, written as they
// are, with no tone mapping.
void writePng8(const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& bytes);

}  // namespace imaging
