// The pipelines of the deferred path (SPEC 3.7), all with one pipeline
// layout:
//   set 0: FrameBlock, ObjectBlock (dynamic offset, the G-buffer pass),
//          DeferredLightBlock (dynamic offset, one per light draw),
//          DeferredFrameBlock;
//   set 1: the object's baked maps, the forward pipeline's layout itself
//          (baked_textures.h), so the same sets bind in both paths;
//   set 2: the G-buffer images and the light buffer;
// each at its binding of shaders/shader_interface.def.
// Each pass binds only the sets its shaders read.
//
// G-buffer pass: forward.vert + gbuffer.frag, five RGBA32F colour outputs and
// D32 depth, LESS with writes, back faces culled (as forward).
// Light pass: deferred_light.vert/.frag into the light buffer, against the
// G-buffer depth read-only; its rasterisation, depth test and blend are the
// model's (lighting::lightVolumeRasterState, lighting::lightBufferState),
// translated by raster_translation.h.
// Composite pass: a full-screen triangle, no depth, into the output image.
// Pipelines are built on first use through the on-disk pipeline cache.
#pragma once

#include "backends/vulkan/pipeline_builder.h"
#include "lighting/deferred_lights.h"

#include <map>
#include <tuple>

namespace backends::vulkan {

class DeferredPipelines {
 public:
  // `mapsSetLayout` and `lightTextureSetLayout` are the forward pipeline's set 1
  // and set 3 layouts; they must outlive this.
  DeferredPipelines(const VulkanDevice& device, const PipelineCacheFile& cache,
                    const vk::raii::DescriptorSetLayout& mapsSetLayout,
                    const vk::raii::DescriptorSetLayout& lightTextureSetLayout);

  const vk::raii::DescriptorSetLayout& uniformsSetLayout() const { return uniformsSetLayout_; }
  const vk::raii::DescriptorSetLayout& texturesSetLayout() const { return texturesSetLayout_; }
  const vk::raii::PipelineLayout& layout() const { return layout_; }

  const vk::raii::Pipeline& gbuffer(const shaders::ConstantValues& constants);
  const vk::raii::Pipeline& light(const shaders::ConstantValues& constants, const lighting::RasterState& raster,
                                  lighting::DeferredBuffer buffer);
  const vk::raii::Pipeline& composite(const shaders::ConstantValues& constants);

 private:
  vk::raii::Pipeline createLight(const shaders::ConstantValues& constants, const lighting::RasterState& raster,
                                 lighting::DeferredBuffer buffer) const;
  vk::raii::Pipeline createComposite(const shaders::ConstantValues& constants) const;

  PipelineBuilder builder_;
  ShaderStages gbufferStages_;    // forward.vert, gbuffer.frag
  ShaderStages lightStages_;      // deferred_light.vert/.frag
  ShaderStages compositeStages_;  // deferred_composite.vert/.frag
  vk::raii::DescriptorSetLayout uniformsSetLayout_{nullptr};
  vk::raii::DescriptorSetLayout texturesSetLayout_{nullptr};
  vk::raii::PipelineLayout layout_{nullptr};
  std::map<shaders::ConstantValues, vk::raii::Pipeline> gbuffer_;
  std::map<std::tuple<shaders::ConstantValues, lighting::RasterState, lighting::DeferredBuffer>, vk::raii::Pipeline>
      light_;
  std::map<shaders::ConstantValues, vk::raii::Pipeline> composite_;
};

}  // namespace backends::vulkan
