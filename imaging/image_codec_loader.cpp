#include "imaging/image_codec_loader.h"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

#ifndef LIGHTCTS_IMAGE_MODULE_PATH
#error "LIGHTCTS_IMAGE_MODULE_PATH: the image module's path, set by imaging/CMakeLists.txt"
#endif

namespace imaging {
namespace {

struct LoadedCodec {
  ImageCodec* codec = nullptr;
  std::string error;  // why it could not be loaded
};

LoadedCodec load() {
  const std::string path = imageModulePath();
  // Never closed: the codec lives as long as the process.
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module) {
    const char* why = dlerror();
    return {nullptr, "cannot load the image module " + path + ": " + (why ? why : "unknown reason") +
                         " (it is built with lightcts; set LIGHTCTS_IMAGE_MODULE to its path if it was moved)"};
  }
  using Entry = ImageCodec* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(module, LIGHTCTS_IMAGE_CODEC_ENTRY));
  if (!entry)
    return {nullptr, "the image module " + path + " has no " LIGHTCTS_IMAGE_CODEC_ENTRY
                     " (a module of another lightcts build?)"};
  return {entry(), {}};
}

}  // namespace

std::string imageModulePath() {
  if (const char* override = std::getenv("LIGHTCTS_IMAGE_MODULE"); override && *override) return override;
  return LIGHTCTS_IMAGE_MODULE_PATH;
}

ImageCodec& imageCodec() {
  static std::once_flag once;
  static LoadedCodec loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded.codec) throw ImageModuleError(loaded.error);
  return *loaded.codec;
}

}  // namespace imaging
