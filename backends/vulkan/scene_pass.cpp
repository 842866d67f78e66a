#include "backends/vulkan/scene_pass.h"

#include "backends/vulkan/descriptor_set_indices.h"
#include "lighting/raster_state.h"

#include <array>

namespace backends::vulkan {
namespace {

constexpr vk::ImageSubresourceRange kColorRange{vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1};
constexpr vk::ImageSubresourceRange kDepthRange{vk::ImageAspectFlagBits::eDepth, 0, 1, 0, 1};
constexpr vk::PipelineStageFlags2 kDepthTests =
    vk::PipelineStageFlagBits2::eEarlyFragmentTests | vk::PipelineStageFlagBits2::eLateFragmentTests;

}  // namespace

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

vk::ImageMemoryBarrier2 discardToDepthAttachment(const DeviceImage& image) {
  return {.srcStageMask = vk::PipelineStageFlagBits2::eAllCommands,
          .srcAccessMask = vk::AccessFlagBits2::eMemoryWrite,
          .dstStageMask = kDepthTests,
          .dstAccessMask =
              vk::AccessFlagBits2::eDepthStencilAttachmentRead | vk::AccessFlagBits2::eDepthStencilAttachmentWrite,
          .oldLayout = vk::ImageLayout::eUndefined,
          .newLayout = vk::ImageLayout::eDepthAttachmentOptimal,
          .image = *image.image,
          .subresourceRange = kDepthRange};
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

vk::ImageMemoryBarrier2 depthAttachmentToReadOnly(const DeviceImage& image) {
  return {.srcStageMask = kDepthTests,
          .srcAccessMask = vk::AccessFlagBits2::eDepthStencilAttachmentWrite,
          .dstStageMask = kDepthTests,
          .dstAccessMask = vk::AccessFlagBits2::eDepthStencilAttachmentRead,
          .oldLayout = vk::ImageLayout::eDepthAttachmentOptimal,
          .newLayout = vk::ImageLayout::eDepthStencilReadOnlyOptimal,
          .image = *image.image,
          .subresourceRange = kDepthRange};
}

void recordBarriers(const vk::raii::CommandBuffer& commands, std::span<const vk::ImageMemoryBarrier2> images) {
  commands.pipelineBarrier2(
      vk::DependencyInfo{.imageMemoryBarrierCount = std::uint32_t(images.size()), .pImageMemoryBarriers = images.data()});
}

vk::RenderingAttachmentInfo clearedColor(const DeviceImage& image, const std::array<float, 4>& rgba) {
  return {.imageView = *image.view,
          .imageLayout = vk::ImageLayout::eColorAttachmentOptimal,
          .loadOp = vk::AttachmentLoadOp::eClear,
          .storeOp = vk::AttachmentStoreOp::eStore,
          .clearValue = vk::ClearColorValue(rgba)};
}

vk::RenderingAttachmentInfo clearedDepth(const DeviceImage& image, vk::AttachmentStoreOp store) {
  return {.imageView = *image.view,
          .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
          .loadOp = vk::AttachmentLoadOp::eClear,
          .storeOp = store,
          .clearValue = vk::ClearDepthStencilValue{lighting::kClearDepth, 0}};
}

void setFlippedViewport(const vk::raii::CommandBuffer& commands, vk::Extent2D extent) {
  commands.setViewport(0, vk::Viewport{.x = 0.0f, .y = float(extent.height), .width = float(extent.width),
                                       .height = -float(extent.height), .minDepth = 0.0f, .maxDepth = 1.0f});
  commands.setScissor(0, vk::Rect2D{{0, 0}, extent});
}

void recordSceneObjectsPass(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                            const SceneObjectsPass& pass) {
  commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, pass.extent},
                                            .layerCount = 1,
                                            .colorAttachmentCount = std::uint32_t(pass.colors.size()),
                                            .pColorAttachments = pass.colors.data(),
                                            .pDepthAttachment = &pass.depth});
  if (pass.flipViewport) {
    setFlippedViewport(commands, pass.extent);
  } else {
    commands.setViewport(0, vk::Viewport{.x = 0.0f, .y = 0.0f, .width = float(pass.extent.width),
                                         .height = float(pass.extent.height), .minDepth = 0.0f, .maxDepth = 1.0f});
    commands.setScissor(0, vk::Rect2D{{0, 0}, pass.extent});
  }
  commands.bindPipeline(vk::PipelineBindPoint::eGraphics, pass.pipeline);
  commands.bindVertexBuffers(0, {*geometry.vertices.buffer}, {vk::DeviceSize(0)});
  commands.bindIndexBuffer(*geometry.indices.buffer, 0, vk::IndexType::eUint32);
  for (std::size_t o = 0; o < geometry.objects.size(); ++o) {
    const ObjectRange& range = geometry.objects[o];
    if (range.indexCount == 0) continue;
    pass.bindUniforms(commands, o);
    if (pass.maps)
      commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, pass.layout, kObjectMapsSetIndex, {pass.maps->set(o)}, {});
    commands.drawIndexed(range.indexCount, 1, range.firstIndex, range.vertexOffset, 0);
  }
  commands.endRendering();
}

}  // namespace backends::vulkan
