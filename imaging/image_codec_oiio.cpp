// The image module (image_codec.h): ImageCodec over OpenImageIO. Built as a
// shared module; the one file of the tree that includes OpenImageIO.
#include "imaging/image_codec.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

namespace imaging {
namespace {

OIIO::TypeDesc typeOf(SampleType type) {
  return type == SampleType::Float32 ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
}

class OiioCodec final : public ImageCodec {
 public:
  std::string write(const std::string& path, int width, int height, int channels, SampleType type,
                    const void* pixels) override {
    OIIO::ImageSpec spec(width, height, channels, typeOf(type));
    if (type == SampleType::Float32) spec.attribute("compression", "zip");
    auto out = OIIO::ImageOutput::create(path);  // the format from the extension
    if (!out) return OIIO::geterror();
    if (!out->open(path, spec) || !out->write_image(typeOf(type), pixels) || !out->close()) return out->geterror();
    return {};
  }

  std::string readFloat(const std::string& path, ChannelChoice choice, Image& image) override {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    int first = 0, count = spec.nchannels;
    if (choice == ChannelChoice::AlphaOrFirst) {
      first = spec.alpha_channel >= 0 ? spec.alpha_channel : 0;
      count = 1;
    }
    image = Image(spec.width, spec.height, count);
    // OIIO converts UNORM levels to floats n / 255 and applies no colour
    // transform unless asked to.
    if (!in->read_image(0, 0, first, first + count, OIIO::TypeDesc::FLOAT, image.pixels.data()))
      return in->geterror();
    return {};
  }

  std::string readUInt8(const std::string& path, Image8& image) override {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.levels.assign(std::size_t(spec.width) * spec.height * spec.nchannels, 0);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, image.levels.data())) return in->geterror();
    return {};
  }

  std::string base64(const std::string& bytes) override { return OIIO::Strutil::base64_encode(bytes); }

  long perceptualDifferences(const float* a, const float* b, int width, int height, float adaptationLuminance,
                             float fieldOfViewDeg, std::string& error) override {
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    // ImageBuf wraps the caller's pixels; compare_Yee only reads them.
    const OIIO::ImageBuf bufA(spec, const_cast<float*>(a)), bufB(spec, const_cast<float*>(b));
    OIIO::ImageBufAlgo::CompareResults result{};  // compare_Yee fills maxerror and the worst pixel only
    const int failing = OIIO::ImageBufAlgo::compare_Yee(bufA, bufB, result, adaptationLuminance, fieldOfViewDeg);
    if (failing < 0) error = bufB.geterror();
    return failing;
  }
};

}  // namespace
}  // namespace imaging

extern "C" __attribute__((visibility("default"))) imaging::ImageCodec* lightcts_image_codec_v1() {
  static imaging::OiioCodec codec;
  return &codec;
}
