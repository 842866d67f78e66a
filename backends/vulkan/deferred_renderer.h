// The deferred path (SPEC 3.7) of the Vulkan backend, recorded into draw()'s
// command buffer in place of the forward pass:
//   1. G-buffer pass: every object, as forward draws it (dynamic object
//      offsets, set 1 maps), into five RGBA32F images and D32 depth;
//   2. light pass: one draw per lighting::lightVolumes(frame) entry into the
//      light buffer, against the G-buffer depth attached read-only;
//   3. composite pass: base + decoded light into the output colour image of
//      frame_resources.h, left in COLOR_ATTACHMENT_OPTIMAL as the forward
//      pass leaves it, so readback() is the same for both paths.
// Barriers between the passes make each pass's attachment writes visible to
// the next pass's fragment-shader reads.
#pragma once

#include "backends/vulkan/baked_textures.h"
#include "backends/vulkan/deferred_pipelines.h"
#include "backends/vulkan/deferred_resources.h"
#include "backends/vulkan/frame_resources.h"
#include "backends/vulkan/gbuffer_targets.h"
#include "backends/vulkan/scene_geometry.h"
#include "shaders/shader_variant.h"

#include <optional>
#include <vector>

namespace backends::vulkan {

class DeferredRenderer {
 public:
  // `mapsSetLayout` and `lightTextureSetLayout` are the forward pipeline's set 1
  // and set 3 layouts (the scene's map sets and the cookie set are allocated
  // with them); they must outlive this.
  DeferredRenderer(const VulkanDevice& device, const PipelineCacheFile& cache,
                   const vk::raii::DescriptorSetLayout& mapsSetLayout,
                   const vk::raii::DescriptorSetLayout& lightTextureSetLayout, const shaders::ShaderVariant& variant);

  // Builds every pipeline a deferred `frame` draws with. Throws
  // NotSupportedError when the device lacks a format feature the frame's
  // buffers need.
  void preparePipelines(const lighting::Frame& frame);
  // Everything a draw of `frame` needs before recording: the targets at its
  // size and light buffer format, its uniforms and light volumes, its pipelines.
  void prepareFrame(const lighting::Frame& frame);
  // The three passes, after prepareFrame(frame) of the frame to draw.
  // `lightTextures` (the cookies and shadow maps) is bound as set 3 for all of them.
  void record(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry, const SceneBakedTextures& maps,
              vk::DescriptorSet lightTextures, const RenderTarget& output) const;

 private:
  // The pipelines of `frame`'s passes and of each of its volumes.
  void choosePipelines(const lighting::Frame& frame, const std::vector<lighting::LightVolume>& volumes);
  void recordGBufferPass(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                         const SceneBakedTextures& maps) const;
  void recordLightPass(const vk::raii::CommandBuffer& commands) const;
  void recordCompositePass(const vk::raii::CommandBuffer& commands, const RenderTarget& output) const;
  void bindUniforms(const vk::raii::CommandBuffer& commands, std::size_t object, std::size_t light) const;

  const VulkanDevice& device_;
  shaders::ShaderVariant variant_;
  DeferredPipelines pipelines_;
  std::optional<GBufferTargets> targets_;
  std::optional<GBufferTextureSets> textureSets_;  // point at targets_: rebuilt with them
  std::optional<DeferredUniforms> uniforms_;
  std::optional<LightVolumeVertices> volumeVertices_;

  // What prepareFrame() chose for the frame being drawn.
  lighting::DeferredBuffer buffer_ = lighting::DeferredBuffer::Hdr32;
  const vk::raii::Pipeline* gbufferPipeline_ = nullptr;
  const vk::raii::Pipeline* compositePipeline_ = nullptr;
  std::vector<const vk::raii::Pipeline*> lightPipelines_;  // one per volume
  std::vector<VolumeRange> volumeRanges_;                  // one per volume
};

}  // namespace backends::vulkan
