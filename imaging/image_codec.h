// The interface between lightcts and its image module, liblightcts_image_codec.so.
//
// OpenImageIO's Debian build binds about 260 shared libraries at load time
// (OpenVDB, GDAL, ffmpeg's codecs, OpenCV, ICU, ...): a third of a second and
// 130 MB before main(). Most lightcts processes read and write no image, so
// OpenImageIO lives in a module that image_codec_loader.cpp opens on first
// use (dlopen). Only the module, image_codec_oiio.cpp, links OpenImageIO
// (suite/bench/run_state.cpp reads its version header, no more).
//
// Module and host are built together by this project with one compiler and
// one libstdc++, so the interface is a C++ class; the entry point is a C
// symbol whose name carries the interface's version. Errors cross it as
// strings, never as exceptions: the host turns them into ImageFileError.
#pragma once

#include "imaging/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace imaging {

enum class SampleType { Float32, UInt8 };

// Which channels a read returns, as float.
enum class ChannelChoice {
  All,           // every channel of the file
  AlphaOrFirst,  // one: the alpha channel when the file has one, else the first
};

// An 8-bit image's levels as stored, row 0 at the top.
struct Image8 {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<std::uint8_t> levels;
};

class ImageCodec {
 public:
  virtual ~ImageCodec() = default;

  // Each returns "" on success, else the reason (without the path).
  // Writes `pixels` (width * height * channels samples of `type`) to `path`
  // in the format its extension names; EXR with zip compression.
  virtual std::string write(const std::string& path, int width, int height, int channels, SampleType type,
                            const void* pixels) = 0;
  // UNORM levels n read as floats n / (2^bits - 1), no colour transform.
  virtual std::string readFloat(const std::string& path, ChannelChoice channels, Image& out) = 0;
  virtual std::string readUInt8(const std::string& path, Image8& out) = 0;

  virtual std::string base64(const std::string& bytes) = 0;

  // Hector Yee's perceptual metric (OpenImageIO's compare_Yee) on two RGB
  // float images of width x height: the count of pixels that differ, or -1
  // with `error` set.
  virtual long perceptualDifferences(const float* a, const float* b, int width, int height,
                                     float adaptationLuminance, float fieldOfViewDeg, std::string& error) = 0;
};

}  // namespace imaging

// The module's one exported symbol: a codec that lives as long as the process.
#define LIGHTCTS_IMAGE_CODEC_ENTRY "lightcts_image_codec_v1"
extern "C" imaging::ImageCodec* lightcts_image_codec_v1();
