#include "backends/vulkan/cookie_textures.h"

#include "backends/backend.h"
#include "backends/cookie_texels.h"
#include "backends/vulkan/texture_upload.h"
#include "lighting/cookie_packing.h"

#include <array>
#include <chrono>
#include <string>

namespace backends::vulkan {
namespace {

constexpr std::uint32_t kTextureSlots = lighting::kMaxCookieTextures;
constexpr std::uint32_t kCubeSlots = lighting::kMaxCookieCubes;
constexpr std::uint32_t kBindingCount = 1 + kTextureSlots + kCubeSlots;  // the block and the slots

constexpr std::array<float, 1> kStandInTexel{1.0f};  // kCookieFormat: the value alone

void requireSize(const VulkanDevice& device, const lighting::Light& light) {
  const bool cube = cookieAddressing(light) == CookieAddressing::Cube;
  const std::uint32_t limit = cube ? device.limits.maxImageDimensionCube : device.limits.maxImageDimension2D;
  const lighting::Cookie& cookie = *light.cookie;
  if (std::uint32_t(cookieWidth(cookie)) > limit || std::uint32_t(cookieHeight(cookie)) > limit)
    throw NotSupportedError(device.info.name + " cannot hold light '" + light.name + "''s " +
                            std::to_string(cookieWidth(cookie)) + " x " + std::to_string(cookieHeight(cookie)) +
                            " cookie (" + (cube ? "maxImageDimensionCube " : "maxImageDimension2D ") +
                            std::to_string(limit) + ")");
}

}  // namespace

CookieTextures::CookieTextures(const VulkanDevice& device, vk::DescriptorSet set)
    : device_(device),
      repeat_(createSingleLevelSampler(device.device, vk::Filter::eLinear, vk::SamplerAddressMode::eRepeat)),
      clamp_(createSingleLevelSampler(device.device, vk::Filter::eLinear, vk::SamplerAddressMode::eClampToEdge)),
      nearest_(createSingleLevelSampler(device.device, vk::Filter::eNearest, vk::SamplerAddressMode::eClampToEdge)),
      noTexture_(createSampledMapImage(device, {1, 1}, kCookieFormat)),
      noCube_(createSampledCubeImage(device, 1, kCookieFormat)),
      block_(device, sizeof(lighting::GpuCookieBlock), vk::BufferUsageFlagBits::eUniformBuffer),
      set_(set) {
  std::vector<float> cube;
  for (int face = 0; face < 6; ++face) cube.insert(cube.end(), kStandInTexel.begin(), kStandInTexel.end());
  const std::array<TextureUpload, 2> uploads{{{&noTexture_, kStandInTexel}, {&noCube_, cube}}};
  uploadTextures(device, uploads);
  const lighting::GpuCookieBlock empty{};
  block_.write(std::span(&empty, 1));
  writeSet(nullptr);
}

void CookieTextures::update(const lighting::Frame& frame) {
  if (frame.prepared != scene_) upload(frame.prepared);
  const lighting::GpuCookieBlock block = lighting::packCookieBlock(frame);
  block_.write(std::span(&block, 1));
  writeSet(&frame);
}

void CookieTextures::upload(const std::shared_ptr<const lighting::PreparedScene>& prepared) {
  const std::vector<lighting::Light>& lights = prepared->scene.lights;
  std::vector<std::optional<DeviceImage>> images(lights.size());
  std::vector<std::vector<float>> texels(lights.size());
  const auto start = std::chrono::steady_clock::now();
  bool any = false;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (!lights[l].cookie) continue;
    if (!any) requireFilterableFormat(device_, kCookieFormat, "the cookies of SPEC 3.10 are sampled bilinearly");
    any = true;
    requireSize(device_, lights[l]);
    const lighting::Cookie& cookie = *lights[l].cookie;
    if (cookieAddressing(lights[l]) == CookieAddressing::Cube)
      images[l].emplace(createSampledCubeImage(device_, std::uint32_t(cookieWidth(cookie)), kCookieFormat));
    else
      images[l].emplace(createSampledMapImage(
          device_, {std::uint32_t(cookieWidth(cookie)), std::uint32_t(cookieHeight(cookie))}, kCookieFormat));
    texels[l] = cookieTexels(cookie);
  }
  std::vector<TextureUpload> uploads;
  for (std::size_t l = 0; l < lights.size(); ++l)
    if (images[l]) uploads.push_back({&*images[l], texels[l]});
  uploadTextures(device_, uploads);
  uploadMilliseconds_ =
      any ? std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() : 0.0;
  // The set points at the old images until writeSet(): the caller writes it
  // next, and no submitted work uses it meanwhile.
  images_ = std::move(images);
  scene_ = prepared;
}

void CookieTextures::writeSet(const lighting::Frame* frame) {
  std::array<vk::DescriptorImageInfo, kBindingCount - 1> images;
  for (std::uint32_t s = 0; s < kTextureSlots; ++s)
    images[s] = {.sampler = *nearest_, .imageView = *noTexture_.view,
                 .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal};
  for (std::uint32_t s = 0; s < kCubeSlots; ++s)
    images[kTextureSlots + s] = {.sampler = *nearest_, .imageView = *noCube_.view,
                                 .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal};
  if (frame) {
    const lighting::CookieSlots& slots = frame->cookies;
    for (std::size_t s = 0; s < slots.textureLights.size(); ++s) {
      const int light = slots.textureLights[s];
      const bool repeat = cookieAddressing(frame->scene().lights[light]) == CookieAddressing::Repeat;
      images[s].sampler = repeat ? *repeat_ : *clamp_;
      images[s].imageView = *images_[light]->view;
    }
    for (std::size_t s = 0; s < slots.cubeLights.size(); ++s) {
      images[kTextureSlots + s].sampler = *clamp_;
      images[kTextureSlots + s].imageView = *images_[slots.cubeLights[s]]->view;
    }
  }
  const vk::DescriptorBufferInfo blockInfo{*block_.buffer, 0, sizeof(lighting::GpuCookieBlock)};
  std::array<vk::WriteDescriptorSet, kBindingCount> writes;
  writes[0] = {.dstSet = set_, .dstBinding = shaders::binding::kCookieBlock.binding, .descriptorCount = 1,
               .descriptorType = vk::DescriptorType::eUniformBuffer, .pBufferInfo = &blockInfo};
  for (std::uint32_t s = 0; s < kTextureSlots + kCubeSlots; ++s)
    writes[1 + s] = {.dstSet = set_,
                     .dstBinding = s < kTextureSlots ? shaders::binding::kCookieTexture.binding(s)
                                                     : shaders::binding::kCookieCube.binding(s - kTextureSlots),
                     .descriptorCount = 1,
                     .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                     .pImageInfo = &images[s]};
  device_.device.updateDescriptorSets(writes, {});
}

}  // namespace backends::vulkan
