#include "backends/vulkan/deferred_resources.h"

#include "backends/aligned_stride.h"
#include "shaders/gbuffer_textures.h"

#include <algorithm>
#include <array>

namespace backends::vulkan {

DeferredUniforms::DeferredUniforms(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout,
                                   std::size_t objectCapacity, std::size_t lightCapacity)
    : scene_(device, objectCapacity),
      lightCapacity_(std::max<std::size_t>(lightCapacity, 1)),
      lightStride_(alignedStride(sizeof(lighting::GpuDeferredLightBlock), device.limits.minUniformBufferOffsetAlignment)),
      lights_(device, lightStride_ * lightCapacity_, vk::BufferUsageFlagBits::eUniformBuffer),
      deferredFrame_(device, sizeof(lighting::GpuDeferredFrameBlock), vk::BufferUsageFlagBits::eUniformBuffer) {
  const std::array<vk::DescriptorPoolSize, 2> perSet{{{vk::DescriptorType::eUniformBuffer, 2},
                                                      {vk::DescriptorType::eUniformBufferDynamic, 2}}};
  descriptors_ = DescriptorSets(device.device, layout, perSet, 1);
  const vk::DescriptorSet set = *descriptors_.sets.front();
  const vk::DescriptorBufferInfo lightInfo{*lights_.buffer, 0, sizeof(lighting::GpuDeferredLightBlock)};
  const vk::DescriptorBufferInfo deferredFrameInfo{*deferredFrame_.buffer, 0, sizeof(lighting::GpuDeferredFrameBlock)};
  const std::array<vk::WriteDescriptorSet, 2> sceneWrites = scene_.descriptorWrites(set);
  const std::array<vk::WriteDescriptorSet, 4> writes{{
      sceneWrites[0],
      sceneWrites[1],
      {.dstSet = set, .dstBinding = shaders::binding::kDeferredLightBlock.binding, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .pBufferInfo = &lightInfo},
      {.dstSet = set, .dstBinding = shaders::binding::kDeferredFrameBlock.binding, .descriptorCount = 1,
       .descriptorType = vk::DescriptorType::eUniformBuffer, .pBufferInfo = &deferredFrameInfo},
  }};
  device.device.updateDescriptorSets(writes, {});
}

std::size_t vertexCount(const std::vector<lighting::LightVolume>& volumes) {
  std::size_t count = 0;
  for (const lighting::LightVolume& v : volumes) count += v.vertices.size();
  return count;
}

LightVolumeVertices::LightVolumeVertices(const VulkanDevice& device, std::size_t vertexCapacity)
    : capacity_(std::max<std::size_t>(vertexCapacity, 3)),
      vertices_(device, capacity_ * sizeof(lighting::GpuVec4), vk::BufferUsageFlagBits::eVertexBuffer) {}

std::vector<VolumeRange> LightVolumeVertices::write(const std::vector<lighting::LightVolume>& volumes) {
  std::vector<VolumeRange> ranges;
  std::uint32_t next = 0;
  for (const lighting::LightVolume& v : volumes) {
    vertices_.write(std::span(v.vertices), next * sizeof(lighting::GpuVec4));
    ranges.push_back({next, std::uint32_t(v.vertices.size())});
    next += std::uint32_t(v.vertices.size());
  }
  return ranges;
}

GBufferTextureSets::GBufferTextureSets(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout,
                                       const GBufferTargets& targets) {
  sampler_ = vk::raii::Sampler(device.device, vk::SamplerCreateInfo{.magFilter = vk::Filter::eNearest,
                                                                    .minFilter = vk::Filter::eNearest,
                                                                    .mipmapMode = vk::SamplerMipmapMode::eNearest,
                                                                    .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                                    .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                                    .addressModeW = vk::SamplerAddressMode::eClampToEdge,
                                                                    .maxLod = 0.0f});
  constexpr std::uint32_t kBindings = kGBufferImageCount + 1;
  const std::array<vk::DescriptorPoolSize, 1> perSet{{{vk::DescriptorType::eCombinedImageSampler, kBindings}}};
  sets_ = DescriptorSets(device.device, layout, perSet, 2);  // [0] light pass, [1] composite

  // The light buffer's binding of the light pass's set is never read there
  // (the light buffer is being drawn); it points at the base image so the
  // set is complete.
  auto info = [&](const DeviceImage& image) {
    return vk::DescriptorImageInfo{*sampler_, *image.view, vk::ImageLayout::eShaderReadOnlyOptimal};
  };
  std::array<std::array<vk::DescriptorImageInfo, kBindings>, 2> infos;
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t b = 0; b < kGBufferImageCount; ++b) infos[s][b] = info(targets.gbuffer[b]);
  infos[0][kGBufferImageCount] = info(targets.gbuffer[std::size_t(lighting::GbufferTarget::Base)]);
  infos[1][kGBufferImageCount] = info(targets.lightBuffer);
  std::vector<vk::WriteDescriptorSet> writes;
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t t = 0; t < kBindings; ++t)
      writes.push_back({.dstSet = *sets_.sets[s],
                        .dstBinding = t < kGBufferImageCount ? shaders::kGbufferTextures[t].binding()
                                                             : shaders::binding::kLightBuffer.binding(),
                        .descriptorCount = 1,
                        .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                        .pImageInfo = &infos[s][t]});
  device.device.updateDescriptorSets(writes, {});
}

}  // namespace backends::vulkan
