#include "backends/vulkan/deferred_renderer.h"

#include "lighting/deferred_lights.h"
#include "lighting/gpu_packing.h"

#include <algorithm>
#include <array>
#include <span>

namespace backends::vulkan {
namespace {

constexpr vk::ImageSubresourceRange kColorRange{vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1};
constexpr vk::ImageSubresourceRange kDepthRange{vk::ImageAspectFlagBits::eDepth, 0, 1, 0, 1};

// As the forward pass: negative height, so NDC y = +1 (up) lands on
// framebuffer row 0, the top of the image. Every pass uses the same one, so a
// pixel is the same texel of every target.
void setViewportAndScissor(const vk::raii::CommandBuffer& commands, vk::Extent2D extent) {
  commands.setViewport(0, vk::Viewport{.x = 0.0f, .y = float(extent.height), .width = float(extent.width),
                                       .height = -float(extent.height), .minDepth = 0.0f, .maxDepth = 1.0f});
  commands.setScissor(0, vk::Rect2D{{0, 0}, extent});
}

vk::ImageMemoryBarrier2 colorAttachmentToSampled(const DeviceImage& image) {
  return {.srcStageMask = vk::PipelineStageFlagBits2::eColorAttachmentOutput,
          .srcAccessMask = vk::AccessFlagBits2::eColorAttachmentWrite,
          .dstStageMask = vk::PipelineStageFlagBits2::eFragmentShader,
          .dstAccessMask = vk::AccessFlagBits2::eShaderSampledRead,
          .oldLayout = vk::ImageLayout::eColorAttachmentOptimal,
          .newLayout = vk::ImageLayout::eShaderReadOnlyOptimal,
          .image = *image.image,
          .subresourceRange = kColorRange};
}

// Whatever the last submission did with an image (a readback copy, a
// sampled read, the last frame's writes) happens before this frame's pass
// overwrites it; nothing of its contents is kept.
vk::ImageMemoryBarrier2 discardToColorAttachment(const DeviceImage& image) {
  return {.srcStageMask = vk::PipelineStageFlagBits2::eAllCommands,
          .srcAccessMask = vk::AccessFlagBits2::eMemoryWrite,
          .dstStageMask = vk::PipelineStageFlagBits2::eColorAttachmentOutput,
          .dstAccessMask = vk::AccessFlagBits2::eColorAttachmentWrite | vk::AccessFlagBits2::eColorAttachmentRead,
          .oldLayout = vk::ImageLayout::eUndefined,
          .newLayout = vk::ImageLayout::eColorAttachmentOptimal,
          .image = *image.image,
          .subresourceRange = kColorRange};
}

vk::RenderingAttachmentInfo clearedColor(const DeviceImage& image, float value, float alpha) {
  return {.imageView = *image.view,
          .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
          .loadOp = vk::AttachmentLoadOp::eClear,
          .storeOp = vk::AttachmentStoreOp::eStore,
          .clearValue = vk::ClearColorValue(std::array<float, 4>{value, value, value, alpha})};
}

void barriers(const vk::raii::CommandBuffer& commands, std::span<const vk::ImageMemoryBarrier2> images) {
  commands.pipelineBarrier2(
      vk::DependencyInfo{.imageMemoryBarrierCount = std::uint32_t(images.size()), .pImageMemoryBarriers = images.data()});
}

}  // namespace

DeferredRenderer::DeferredRenderer(const VulkanDevice& device, const PipelineCacheFile& cache,
                                   const vk::raii::DescriptorSetLayout& mapsSetLayout,
                                   const shaders::ShaderVariant& variant)
    : device_(device), variant_(variant), pipelines_(device, cache, mapsSetLayout) {}

void DeferredRenderer::preparePipelines(const lighting::Frame& frame) {
  choosePipelines(frame, lighting::lightVolumes(frame));
}

void DeferredRenderer::choosePipelines(const lighting::Frame& frame,
                                       const std::vector<lighting::LightVolume>& volumes) {
  const lighting::DeferredBuffer buffer = frame.scene().pipeline.deferredBuffer;
  requireDeferredFormats(device_, buffer);
  const shaders::ConstantValues constants = shaders::constantValues(frame.features, variant_);
  gbufferPipeline_ = &pipelines_.gbuffer(constants);
  compositePipeline_ = &pipelines_.composite(constants);
  lightPipelines_.clear();
  for (const lighting::LightVolume& volume : volumes)
    lightPipelines_.push_back(
        &pipelines_.light(constants, lightVolumeDraw(volume.shape, variant_.mutant), lightBufferFormat(buffer)));
}

void DeferredRenderer::prepareFrame(const lighting::Frame& frame) {
  const std::vector<lighting::LightVolume> volumes = lighting::lightVolumes(frame);
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
  uniforms_->write(lighting::packFrameBlock(frame));
  uniforms_->write(lighting::packDeferredFrame(frame));
  for (std::size_t o = 0; o < objectCount; ++o) uniforms_->write(o, lighting::packObjectBlock(frame, int(o)));
  for (std::size_t l = 0; l < volumes.size(); ++l)
    uniforms_->write(l, lighting::packDeferredLight(frame, volumes[l].light));

  if (!volumeVertices_ || volumeVertices_->vertexCapacity() < vertexCount(volumes)) {
    volumeVertices_.reset();
    volumeVertices_.emplace(device_, vertexCount(volumes));
  }
  volumeRanges_ = volumeVertices_->write(volumes);
}

void DeferredRenderer::record(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                              const SceneBakedTextures& maps, const RenderTarget& output) const {
  std::vector<vk::ImageMemoryBarrier2> start;
  for (const DeviceImage& image : targets_->gbuffer) start.push_back(discardToColorAttachment(image));
  start.push_back(discardToColorAttachment(targets_->lightBuffer));
  start.push_back(discardToColorAttachment(output.color));
  start.push_back({.srcStageMask = vk::PipelineStageFlagBits2::eAllCommands,
                   .srcAccessMask = vk::AccessFlagBits2::eMemoryWrite,
                   .dstStageMask = vk::PipelineStageFlagBits2::eEarlyFragmentTests |
                                   vk::PipelineStageFlagBits2::eLateFragmentTests,
                   .dstAccessMask = vk::AccessFlagBits2::eDepthStencilAttachmentRead |
                                    vk::AccessFlagBits2::eDepthStencilAttachmentWrite,
                   .oldLayout = vk::ImageLayout::eUndefined,
                   .newLayout = vk::ImageLayout::eDepthAttachmentOptimal,
                   .image = *targets_->depth.image,
                   .subresourceRange = kDepthRange});
  barriers(commands, start);

  recordGBufferPass(commands, geometry, maps);

  // The G-buffer's colour writes before the light pass samples them; its
  // depth writes before the light pass tests against it, read-only.
  std::vector<vk::ImageMemoryBarrier2> afterGBuffer;
  for (const DeviceImage& image : targets_->gbuffer) afterGBuffer.push_back(colorAttachmentToSampled(image));
  afterGBuffer.push_back({.srcStageMask = vk::PipelineStageFlagBits2::eEarlyFragmentTests |
                                          vk::PipelineStageFlagBits2::eLateFragmentTests,
                          .srcAccessMask = vk::AccessFlagBits2::eDepthStencilAttachmentWrite,
                          .dstStageMask = vk::PipelineStageFlagBits2::eEarlyFragmentTests |
                                          vk::PipelineStageFlagBits2::eLateFragmentTests,
                          .dstAccessMask = vk::AccessFlagBits2::eDepthStencilAttachmentRead,
                          .oldLayout = vk::ImageLayout::eDepthAttachmentOptimal,
                          .newLayout = vk::ImageLayout::eDepthStencilReadOnlyOptimal,
                          .image = *targets_->depth.image,
                          .subresourceRange = kDepthRange});
  barriers(commands, afterGBuffer);

  recordLightPass(commands);

  // The light buffer's blended writes before the composite samples it.
  const std::array<vk::ImageMemoryBarrier2, 1> afterLights{colorAttachmentToSampled(targets_->lightBuffer)};
  barriers(commands, afterLights);

  recordCompositePass(commands, output);
}

void DeferredRenderer::bindUniforms(const vk::raii::CommandBuffer& commands, std::size_t object,
                                    std::size_t light) const {
  const std::array<std::uint32_t, 2> offsets = uniforms_->offsets(object, light);
  commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), 0, {*uniforms_->descriptorSet()},
                              offsets);
}

void DeferredRenderer::recordGBufferPass(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                                         const SceneBakedTextures& maps) const {
  // Everything cleared to 0: albedo.a = 0 marks the background for the light pass.
  std::array<vk::RenderingAttachmentInfo, kGBufferImageCount> colors;
  for (std::size_t i = 0; i < kGBufferImageCount; ++i) colors[i] = clearedColor(targets_->gbuffer[i], 0.0f, 0.0f);
  const vk::RenderingAttachmentInfo depth{
      .imageView = *targets_->depth.view,
      .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
      .loadOp = vk::AttachmentLoadOp::eClear,
      .storeOp = vk::AttachmentStoreOp::eStore,  // the light pass tests against it
      .clearValue = vk::ClearDepthStencilValue{1.0f, 0},
  };
  commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, targets_->extent},
                                            .layerCount = 1,
                                            .colorAttachmentCount = colors.size(),
                                            .pColorAttachments = colors.data(),
                                            .pDepthAttachment = &depth});
  setViewportAndScissor(commands, targets_->extent);
  commands.bindPipeline(vk::PipelineBindPoint::eGraphics, **gbufferPipeline_);
  commands.bindVertexBuffers(0, {*geometry.vertices.buffer}, {vk::DeviceSize(0)});
  commands.bindIndexBuffer(*geometry.indices.buffer, 0, vk::IndexType::eUint32);
  for (std::size_t o = 0; o < geometry.objects.size(); ++o) {
    const ObjectRange& range = geometry.objects[o];
    if (range.indexCount == 0) continue;
    bindUniforms(commands, o, 0);
    // Every object binds set 1, maps or not: gbuffer.frag declares it.
    commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), 1, {maps.set(o)}, {});
    commands.drawIndexed(range.indexCount, 1, range.firstIndex, range.vertexOffset, 0);
  }
  commands.endRendering();
}

void DeferredRenderer::recordLightPass(const vk::raii::CommandBuffer& commands) const {
  // The blend's identity: hdr sums from 0, ldr8 multiplies from 1.
  const float clear = buffer_ == lighting::DeferredBuffer::Ldr8 ? 1.0f : 0.0f;
  const vk::RenderingAttachmentInfo color = clearedColor(targets_->lightBuffer, clear, clear);
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
    setViewportAndScissor(commands, targets_->extent);
    commands.bindVertexBuffers(0, {*volumeVertices_->buffer()}, {vk::DeviceSize(0)});
    commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), 2, {textureSets_->lightPass()},
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
  const vk::RenderingAttachmentInfo color = clearedColor(output.color, 0.0f, 1.0f);
  commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, output.color.extent},
                                            .layerCount = 1,
                                            .colorAttachmentCount = 1,
                                            .pColorAttachments = &color});
  setViewportAndScissor(commands, output.color.extent);
  commands.bindPipeline(vk::PipelineBindPoint::eGraphics, **compositePipeline_);
  bindUniforms(commands, 0, 0);
  commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), 2, {textureSets_->composite()}, {});
  commands.draw(3, 1, 0, 0);
  commands.endRendering();
}

}  // namespace backends::vulkan
