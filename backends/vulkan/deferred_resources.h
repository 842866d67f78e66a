// What the deferred passes read besides the scene's geometry and maps:
//   DeferredUniforms: set 0 of deferred_pipelines.h: the scene's uniforms
//     (scene_uniforms.h, as the forward pass has them), one light block per
//     light draw at the device's dynamic-offset alignment, the deferred frame
//     block;
//   LightVolumeVertices: every light volume of the frame in one host-visible
//     vertex buffer, written each frame (the volumes follow the camera);
//   GBufferTextureSets: set 2, once for the light pass and once for the
//     composite pass (only the composite's points lightBuffer at the light
//     buffer: during the light pass that image is the attachment).
// The first two grow (are rebuilt) only when a frame needs more than they
// hold; the sets are rebuilt with the targets they point at.
#pragma once

#include "backends/vulkan/gbuffer_targets.h"
#include "backends/vulkan/descriptor_sets.h"
#include "backends/vulkan/gpu_memory.h"
#include "backends/vulkan/scene_uniforms.h"
#include "lighting/deferred_lights.h"
#include "lighting/gpu_packing.h"

#include <array>
#include <span>
#include <vector>

namespace backends::vulkan {

class DeferredUniforms {
 public:
  DeferredUniforms(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout, std::size_t objectCapacity,
                   std::size_t lightCapacity);

  SceneUniforms& scene() { return scene_; }
  std::size_t objectCapacity() const { return scene_.objectCapacity(); }
  std::size_t lightCapacity() const { return lightCapacity_; }
  const vk::raii::DescriptorSet& descriptorSet() const { return descriptors_.sets.front(); }
  // The two dynamic offsets of set 0, in binding order (object, light).
  std::array<std::uint32_t, 2> offsets(std::size_t object, std::size_t light) const {
    return {scene_.objectOffset(object), std::uint32_t(light * lightStride_)};
  }
  void write(const lighting::GpuDeferredFrameBlock& frame) { deferredFrame_.write(std::span(&frame, 1)); }
  void write(std::size_t light, const lighting::GpuDeferredLightBlock& block) {
    lights_.write(std::span(&block, 1), light * lightStride_);
  }

 private:
  SceneUniforms scene_;  // the frame and object blocks, as in the forward pass
  std::size_t lightCapacity_;
  vk::DeviceSize lightStride_;
  HostBuffer lights_;
  HostBuffer deferredFrame_;
  DescriptorSets descriptors_;  // the one set 0 pointing at the buffers
};

// Where one volume's triangles are in the vertex buffer.
struct VolumeRange {
  std::uint32_t firstVertex = 0;
  std::uint32_t vertexCount = 0;
};

class LightVolumeVertices {
 public:
  LightVolumeVertices(const VulkanDevice& device, std::size_t vertexCapacity);

  std::size_t vertexCapacity() const { return capacity_; }
  const vk::raii::Buffer& buffer() const { return vertices_.buffer; }
  // Writes every volume's vertices one after the other; the caller made sure
  // they fit (vertexCapacity()).
  std::vector<VolumeRange> write(const std::vector<lighting::LightVolume>& volumes);

 private:
  std::size_t capacity_;
  HostBuffer vertices_;
};

std::size_t vertexCount(const std::vector<lighting::LightVolume>& volumes);

class GBufferTextureSets {
 public:
  GBufferTextureSets(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout,
                     const GBufferTargets& targets);

  vk::DescriptorSet lightPass() const { return *sets_.sets[0]; }
  vk::DescriptorSet composite() const { return *sets_.sets[1]; }

 private:
  // texelFetch ignores filtering; NEAREST asks nothing of the formats.
  vk::raii::Sampler sampler_{nullptr};
  DescriptorSets sets_;
};

}  // namespace backends::vulkan
