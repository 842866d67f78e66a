#include "backends/vulkan/deferred_renderer.h"

#include "backends/vulkan/light_texture_set.h"
#include "backends/vulkan/scene_pass.h"
#include "lighting/deferred_lights.h"
#include "lighting/gpu_packing.h"

#include <algorithm>
#include <array>

namespace backends::vulkan {

DeferredRenderer::DeferredRenderer(const VulkanDevice& device, const PipelineCacheFile& cache,
                                   const vk::raii::DescriptorSetLayout& mapsSetLayout,
                                   const vk::raii::DescriptorSetLayout& lightTextureSetLayout,
                                   const shaders::ShaderVariant& variant)
    : device_(device), variant_(variant), pipelines_(device, cache, mapsSetLayout, lightTextureSetLayout) {}

void DeferredRenderer::preparePipelines(const lighting::Frame& frame) {
  choosePipelines(frame, shaders::lightVolumesInBlendOrder(frame, variant_));
}

void DeferredRenderer::choosePipelines(const lighting::Frame& frame,
                                       const std::vector<lighting::LightVolume>& volumes) {
  const lighting::DeferredBuffer buffer = frame.scene().pipeline.deferredBuffer;
  requireDeferredFormats(device_, buffer);
  const shaders::ConstantValues constants = shaders::constantValues(frame.features, variant_);
  gbufferPipeline_ = &pipelines_.gbuffer(constants);
  compositePipeline_ = &pipelines_.composite(constants);
  lightPipelines_.clear();
  // Each light's pass looks up that light's texture slots alone.
  for (const lighting::LightVolume& volume : volumes)
    lightPipelines_.push_back(
        &pipelines_.light(shaders::lightPassConstants(constants, volume.slots, variant_),
                          lighting::lightVolumeRasterState(volume.shape, shaders::volumeRule(variant_.mutant)), buffer));
}

void DeferredRenderer::prepareFrame(const lighting::Frame& frame) {
  const std::vector<lighting::LightVolume> volumes = shaders::lightVolumesInBlendOrder(frame, variant_);
  choosePipelines(frame, volumes);
  buffer_ = frame.scene().pipeline.deferredBuffer;
  const vk::Extent2D extent{std::uint32_t(frame.scene().image.width), std::uint32_t(frame.scene().image.height)};
  if (!targets_ || !targets_->fits(extent, buffer_)) {
    textureSets_.reset();  // before the images it points at
    targets_.reset();
    targets_.emplace(device_, extent, buffer_);
    textureSets_.emplace(device_, pipelines_.texturesSetLayout(), *targets_);
  }

  const std::size_t objectCount = frame.scene().objects.size();
  if (!uniforms_ || uniforms_->objectCapacity() < objectCount || uniforms_->lightCapacity() < volumes.size()) {
    const std::size_t objects = std::max(objectCount, uniforms_ ? uniforms_->objectCapacity() : 0);
    const std::size_t lights = std::max(volumes.size(), uniforms_ ? uniforms_->lightCapacity() : 0);
    uniforms_.reset();
    uniforms_.emplace(device_, pipelines_.uniformsSetLayout(), objects, lights);
  }
  uniforms_->scene().write(frame);
  uniforms_->write(lighting::packDeferredFrame(frame));
  for (std::size_t l = 0; l < volumes.size(); ++l)
    uniforms_->write(l, lighting::packDeferredLight(frame, volumes[l].light));

  if (!volumeVertices_ || volumeVertices_->vertexCapacity() < vertexCount(volumes)) {
    volumeVertices_.reset();
    volumeVertices_.emplace(device_, vertexCount(volumes));
  }
  volumeRanges_ = volumeVertices_->write(volumes);
}

void DeferredRenderer::record(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                              const SceneBakedTextures& maps, vk::DescriptorSet lightTextures,
                              const RenderTarget& output) const {
  std::vector<vk::ImageMemoryBarrier2> start;
  for (const DeviceImage& image : targets_->gbuffer) start.push_back(discardToColorAttachment(image));
  start.push_back(discardToColorAttachment(targets_->lightBuffer));
  start.push_back(discardToColorAttachment(output.color));
  start.push_back(discardToDepthAttachment(targets_->depth));
  recordBarriers(commands, start);
  // One pipeline layout for the three passes: set 3 stays bound through them.
  commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), kLightTextureSetIndex, {lightTextures}, {});

  recordGBufferPass(commands, geometry, maps);

  // The G-buffer's colour writes before the light pass samples them; its
  // depth writes before the light pass tests against it, read-only.
  std::vector<vk::ImageMemoryBarrier2> afterGBuffer;
  for (const DeviceImage& image : targets_->gbuffer) afterGBuffer.push_back(colorAttachmentToSampled(image));
  afterGBuffer.push_back(depthAttachmentToReadOnly(targets_->depth));
  recordBarriers(commands, afterGBuffer);

  recordLightPass(commands);

  // The light buffer's blended writes before the composite samples it.
  const std::array<vk::ImageMemoryBarrier2, 1> afterLights{colorAttachmentToSampled(targets_->lightBuffer)};
  recordBarriers(commands, afterLights);

  recordCompositePass(commands, output);
}

void DeferredRenderer::bindUniforms(const vk::raii::CommandBuffer& commands, std::size_t object,
                                    std::size_t light) const {
  const std::array<std::uint32_t, 2> offsets = uniforms_->offsets(object, light);
  commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), kSceneSetIndex, {*uniforms_->descriptorSet()},
                              offsets);
}

void DeferredRenderer::recordGBufferPass(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                                         const SceneBakedTextures& maps) const {
  // Everything cleared to 0: albedo.a = 0 marks the background for the light pass.
  std::array<vk::RenderingAttachmentInfo, kGBufferImageCount> colors;
  for (std::size_t i = 0; i < kGBufferImageCount; ++i) colors[i] = clearedColor(targets_->gbuffer[i], lighting::kGbufferClear);
  recordSceneObjectsPass(commands, geometry,
                         {.colors = colors,
                          // Stored: the light pass tests against it.
                          .depth = clearedDepth(targets_->depth, vk::AttachmentStoreOp::eStore),
                          .extent = targets_->extent,
                          .pipeline = **gbufferPipeline_,
                          .layout = *pipelines_.layout(),
                          .bindUniforms = [this](const vk::raii::CommandBuffer& cb,
                                                 std::size_t object) { bindUniforms(cb, object, 0); },
                          .maps = &maps});
}

void DeferredRenderer::recordLightPass(const vk::raii::CommandBuffer& commands) const {
  // The blend's identity (lighting::lightBufferState).
  const float clear = lighting::lightBufferState(buffer_).clearValue;
  const vk::RenderingAttachmentInfo color = clearedColor(targets_->lightBuffer, {clear, clear, clear, clear});
  // The G-buffer depth, read-only: tested, never written, never sampled.
  const vk::RenderingAttachmentInfo depth{
      .imageView = *targets_->depth.view,
      .imageLayout = vk::ImageLayout::eDepthStencilReadOnlyOptimal,
      .loadOp = vk::AttachmentLoadOp::eLoad,
      .storeOp = vk::AttachmentStoreOp::eNone,
  };
  commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, targets_->extent},
                                            .layerCount = 1,
                                            .colorAttachmentCount = 1,
                                            .pColorAttachments = &color,
                                            .pDepthAttachment = &depth});
  if (!volumeRanges_.empty()) {
    setFlippedViewport(commands, targets_->extent);
    commands.bindVertexBuffers(0, {*volumeVertices_->buffer()}, {vk::DeviceSize(0)});
    commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), kGbufferSetIndex, {textureSets_->lightPass()},
                                {});
    const vk::raii::Pipeline* bound = nullptr;
    for (std::size_t l = 0; l < volumeRanges_.size(); ++l) {
      if (lightPipelines_[l] != bound) {
        bound = lightPipelines_[l];
        commands.bindPipeline(vk::PipelineBindPoint::eGraphics, **bound);
      }
      bindUniforms(commands, 0, l);
      commands.draw(volumeRanges_[l].vertexCount, 1, volumeRanges_[l].firstVertex, 0);
    }
  }
  commands.endRendering();
}

void DeferredRenderer::recordCompositePass(const vk::raii::CommandBuffer& commands, const RenderTarget& output) const {
  // The triangle covers every pixel; the clear only keeps A = 1 obvious.
  const vk::RenderingAttachmentInfo color = clearedColor(output.color, lighting::kBackgroundClear);
  commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, output.color.extent},
                                            .layerCount = 1,
                                            .colorAttachmentCount = 1,
                                            .pColorAttachments = &color});
  setFlippedViewport(commands, output.color.extent);
  commands.bindPipeline(vk::PipelineBindPoint::eGraphics, **compositePipeline_);
  bindUniforms(commands, 0, 0);
  commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), kGbufferSetIndex, {textureSets_->composite()}, {});
  commands.draw(3, 1, 0, 0);
  commands.endRendering();
}

}  // namespace backends::vulkan
