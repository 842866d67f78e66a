// The pipelines of the deferred path (SPEC 3.7), all with one pipeline
// layout:
//   set 0: binding 0 FrameBlock, binding 1 ObjectBlock (dynamic offset, the
//          G-buffer pass), binding 2 DeferredLightBlock (dynamic offset, one
//          per light draw), binding 3 DeferredFrameBlock;
//   set 1: the object's baked maps, the forward pipeline's layout itself
//          (baked_textures.h), so the same sets bind in both paths;
//   set 2: the G-buffer images (bindings 0-3) and the light buffer (4).
// Each pass binds only the sets its shaders read.
//
// G-buffer pass: forward.vert + gbuffer.frag, four RGBA32F colour outputs and
// D32 depth, LESS with writes, back faces culled (as forward).
// Light pass: deferred_light.vert/.frag into the light buffer, blending ONE,
// ONE (hdr) or DST_COLOR, ZERO (ldr8), against the G-buffer depth read-only;
// its rasterisation and depth test depend on the volume (LightVolumeDraw).
// Composite pass: a full-screen triangle, no depth, into the output image.
// Pipelines are built on first use through the on-disk pipeline cache.
#pragma once

#include "backends/vulkan/pipeline_cache_file.h"
#include "backends/vulkan/vulkan_device.h"
#include "lighting/deferred_lights.h"
#include "shaders/shader_constants.h"

#include <map>
#include <tuple>

namespace backends::vulkan {

// How the light pass rasterises one volume.
enum class LightVolumeDraw {
  // Directional lights: the full-screen triangle, no culling, depth ALWAYS.
  FullScreen,
  // Point and spot volumes: back faces only, depth GREATER_OR_EQUAL against
  // the G-buffer depth, depth clamp where the device has it. A ray through a
  // pixel leaves a closed convex volume exactly once, so each surface point
  // inside is lit once, also with the camera inside the volume.
  BackFacesBehindSurface,
  // Mutant point-volume-outside-only: front faces with depth LESS_OR_EQUAL,
  // which draws nothing for a volume around the camera.
  FrontFacesBeforeSurface,
};

// What a volume of `shape` is drawn with under `mutant`; the mutant affects
// icosphere volumes only (points, and spots too wide for a pyramid).
LightVolumeDraw lightVolumeDraw(lighting::LightVolumeShape shape, shaders::Mutant mutant);

class DeferredPipelines {
 public:
  // `mapsSetLayout` is the forward pipeline's set 1 layout; it must outlive this.
  DeferredPipelines(const VulkanDevice& device, const PipelineCacheFile& cache,
                    const vk::raii::DescriptorSetLayout& mapsSetLayout);

  const vk::raii::DescriptorSetLayout& uniformsSetLayout() const { return uniformsSetLayout_; }
  const vk::raii::DescriptorSetLayout& texturesSetLayout() const { return texturesSetLayout_; }
  const vk::raii::PipelineLayout& layout() const { return layout_; }

  const vk::raii::Pipeline& gbuffer(const shaders::ConstantValues& constants);
  const vk::raii::Pipeline& light(const shaders::ConstantValues& constants, LightVolumeDraw draw,
                                  vk::Format lightBufferFormat);
  const vk::raii::Pipeline& composite(const shaders::ConstantValues& constants);

 private:
  vk::raii::Pipeline createGBuffer(const shaders::ConstantValues& constants) const;
  vk::raii::Pipeline createLight(const shaders::ConstantValues& constants, LightVolumeDraw draw,
                                 vk::Format lightBufferFormat) const;
  vk::raii::Pipeline createComposite(const shaders::ConstantValues& constants) const;

  const VulkanDevice& device_;
  const PipelineCacheFile& cache_;
  vk::raii::DescriptorSetLayout uniformsSetLayout_{nullptr};
  vk::raii::DescriptorSetLayout texturesSetLayout_{nullptr};
  vk::raii::PipelineLayout layout_{nullptr};
  vk::raii::ShaderModule forwardVertex_{nullptr};
  vk::raii::ShaderModule gbufferFragment_{nullptr};
  vk::raii::ShaderModule lightVertex_{nullptr};
  vk::raii::ShaderModule lightFragment_{nullptr};
  vk::raii::ShaderModule compositeVertex_{nullptr};
  vk::raii::ShaderModule compositeFragment_{nullptr};
  std::map<shaders::ConstantValues, vk::raii::Pipeline> gbuffer_;
  std::map<std::tuple<shaders::ConstantValues, LightVolumeDraw, vk::Format>, vk::raii::Pipeline> light_;
  std::map<shaders::ConstantValues, vk::raii::Pipeline> composite_;
};

}  // namespace backends::vulkan
