// Opens the image module (image_codec.h) on first use. A process that reads
// and writes no image never loads it, nor OpenImageIO and what it brings.
#pragma once

#include "imaging/image_codec.h"

#include <stdexcept>
#include <string>

namespace imaging {

// The image module could not be loaded: an installation fault, not bad
// input (lightcts exits 4 with this message, which names the module's path).
class ImageModuleError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where the module is looked for: $LIGHTCTS_IMAGE_MODULE when set (a moved
// build, or a test of the failure), else the path this build wrote it to.
std::string imageModulePath();

// The loaded codec; loads the module on the first call (thread-safe).
// Throws ImageModuleError when it cannot be loaded; every later call throws
// the same message again.
ImageCodec& imageCodec();

// Commands that will write images call this first, so that a missing module
// stops them before they write anything.
inline void requireImageModule() { imageCodec(); }

}  // namespace imaging
