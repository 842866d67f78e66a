#include "backends/vulkan/baked_textures.h"

#include "backends/vulkan/texture_upload.h"
#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <array>
#include <chrono>
#include <string>

namespace backends::vulkan {
namespace {

constexpr std::array<float, 4> kNoLightmapTexel{0.0f, 0.0f, 0.0f, 1.0f};
constexpr std::array<float, 4> kNoShadowMaskTexel{1.0f, 1.0f, 1.0f, 1.0f};
// The set's two maps, in writeSet's order.
constexpr std::array kMaps = {shaders::binding::kLightmapTexture, shaders::binding::kShadowMaskTexture};

struct BoundMap {
  const DeviceImage* image;
  const vk::raii::Sampler* sampler;
};

void writeSet(const vk::raii::Device& device, vk::DescriptorSet set, BoundMap lightmap, BoundMap shadowMask) {
  const std::array<vk::DescriptorImageInfo, 2> images{{
      {.sampler = **lightmap.sampler, .imageView = *lightmap.image->view,
       .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal},
      {.sampler = **shadowMask.sampler, .imageView = *shadowMask.image->view,
       .imageLayout = vk::ImageLayout::eShaderReadOnlyOptimal},
  }};
  std::array<vk::WriteDescriptorSet, 2> writes;
  for (std::uint32_t b = 0; b < 2; ++b)
    writes[b] = {.dstSet = set, .dstBinding = kMaps[b].binding(), .descriptorCount = 1,
                 .descriptorType = vk::DescriptorType::eCombinedImageSampler, .pImageInfo = &images[b]};
  device.updateDescriptorSets(writes, {});
}

// One set holds the two maps (lightmapTexture, shadowMaskTexture).
constexpr std::array<vk::DescriptorPoolSize, 1> kMapsPerSet{{{vk::DescriptorType::eCombinedImageSampler, 2}}};

}  // namespace

vk::raii::DescriptorSetLayout createBakedMapsSetLayout(const vk::raii::Device& device) {
  std::array<vk::DescriptorSetLayoutBinding, 2> bindings;
  for (std::uint32_t b = 0; b < 2; ++b)
    bindings[b] = {.binding = kMaps[b].binding(), .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                   .descriptorCount = 1, .stageFlags = vk::ShaderStageFlagBits::eFragment};
  return vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = bindings.size(), .pBindings = bindings.data()});
}

BakedMapDefaults::BakedMapDefaults(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout)
    : bilinear_(createSingleLevelSampler(device.device, vk::Filter::eLinear, vk::SamplerAddressMode::eClampToEdge)),
      nearest_(createSingleLevelSampler(device.device, vk::Filter::eNearest, vk::SamplerAddressMode::eClampToEdge)),
      noLightmap_(createSampledMapImage(device, {1, 1})),
      noShadowMask_(createSampledMapImage(device, {1, 1})) {
  const std::array<TextureUpload, 2> uploads{{{&noLightmap_, kNoLightmapTexel}, {&noShadowMask_, kNoShadowMaskTexel}}};
  uploadTextures(device, uploads);
  sets_ = DescriptorSets(device.device, layout, kMapsPerSet, 1);
  writeSet(device.device, *sets_.sets.front(), {&noLightmap_, &nearest_}, {&noShadowMask_, &nearest_});
}

SceneBakedTextures::SceneBakedTextures(const VulkanDevice& device, const BakedMapDefaults& defaults,
                                       const vk::raii::DescriptorSetLayout& layout,
                                       std::shared_ptr<const lighting::PreparedScene> prepared)
    : prepared_(std::move(prepared)), baked_(prepared_->baked) {
  const std::size_t objectCount = prepared_->scene.objects.size();
  std::vector<const lighting::ObjectBake*> bakes(objectCount);
  std::uint32_t withMaps = 0;
  bool anyTexels = false;
  for (std::size_t o = 0; o < objectCount; ++o) {
    bakes[o] = prepared_->bakeOf(int(o));  // throws when the bake is missing
    if (!bakes[o]) continue;
    ++withMaps;
    for (const lighting::TexelMap* map : {&bakes[o]->lightmap, &bakes[o]->shadowMask}) {
      if (map->empty()) continue;
      anyTexels = true;
      if (std::uint32_t(map->resolution) > device.limits.maxImageDimension2D)
        throw NotSupportedError(device.info.name + " cannot hold a " + std::to_string(map->resolution) +
                                "-texel map (maxImageDimension2D " +
                                std::to_string(device.limits.maxImageDimension2D) + ")");
    }
  }
  sets_.assign(objectCount, defaults.noMapsSet());
  if (withMaps == 0) return;
  if (anyTexels)
    requireFilterableFormat(device, kSampledMapFormat,
                            "the lightmaps and shadow masks of SPEC 3.5 and 3.6 are sampled bilinearly from such images");

  const auto start = std::chrono::steady_clock::now();
  // One image per non-empty map; every image is made before the uploads
  // point at them, so no later push_back moves one under a pointer.
  struct ObjectImages {
    std::ptrdiff_t lightmap = -1, shadowMask = -1;  // index in images_, -1: the stand-in
  };
  std::vector<ObjectImages> objectImages(objectCount);
  for (std::size_t o = 0; o < objectCount; ++o) {
    if (!bakes[o]) continue;
    auto add = [&](const lighting::TexelMap& map) -> std::ptrdiff_t {
      if (map.empty()) return -1;
      const auto n = std::uint32_t(map.resolution);
      images_.push_back(createSampledMapImage(device, {n, n}));
      return std::ptrdiff_t(images_.size() - 1);
    };
    objectImages[o] = {add(bakes[o]->lightmap), add(bakes[o]->shadowMask)};
  }
  std::vector<TextureUpload> uploads;
  for (std::size_t o = 0; o < objectCount; ++o) {
    if (objectImages[o].lightmap >= 0) uploads.push_back({&images_[objectImages[o].lightmap], bakes[o]->lightmap.texels});
    if (objectImages[o].shadowMask >= 0)
      uploads.push_back({&images_[objectImages[o].shadowMask], bakes[o]->shadowMask.texels});
  }
  uploadTextures(device, uploads);

  ownSets_ = DescriptorSets(device.device, layout, kMapsPerSet, std::uint32_t(withMaps));
  std::size_t next = 0;
  for (std::size_t o = 0; o < objectCount; ++o) {
    if (!bakes[o]) continue;
    const ObjectImages& im = objectImages[o];
    const BoundMap lightmap = im.lightmap >= 0 ? BoundMap{&images_[im.lightmap], &defaults.bilinear()}
                                               : BoundMap{&defaults.noLightmap(), &defaults.nearest()};
    const BoundMap shadowMask = im.shadowMask >= 0 ? BoundMap{&images_[im.shadowMask], &defaults.bilinear()}
                                                   : BoundMap{&defaults.noShadowMask(), &defaults.nearest()};
    sets_[o] = *ownSets_.sets[next++];
    writeSet(device.device, sets_[o], lightmap, shadowMask);
  }
  uploadMilliseconds_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace backends::vulkan
