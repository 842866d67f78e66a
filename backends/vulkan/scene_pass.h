// Recording a pass, the one way every pass of the Vulkan backend does it:
// the barriers that hand an image to a pass, the cleared attachments, the
// flipped viewport, and the one loop that draws the scene's objects
// (recordSceneObjectsPass), which the forward pass and the deferred G-buffer
// pass share. A depth-only pass of every object (a shadow map from a light's
// view) is the same call with no colour attachment, no maps and its own
// uniforms binder.
#pragma once

#include "backends/vulkan/baked_textures.h"
#include "backends/vulkan/gpu_memory.h"
#include "backends/vulkan/scene_geometry.h"

#include <array>
#include <cstddef>
#include <functional>
#include <span>

namespace backends::vulkan {

// Whatever the last submission did with an image (a readback copy, a sampled
// read, the last frame's writes) happens before this pass overwrites it;
// nothing of its contents is kept.
vk::ImageMemoryBarrier2 discardToColorAttachment(const DeviceImage& image);
vk::ImageMemoryBarrier2 discardToDepthAttachment(const DeviceImage& image);
// A colour attachment's writes before a later pass's fragment stage samples it.
vk::ImageMemoryBarrier2 colorAttachmentToSampled(const DeviceImage& image);
// A depth attachment's writes before a later pass tests against it, attached
// read-only (the deferred light pass against the G-buffer depth).
vk::ImageMemoryBarrier2 depthAttachmentToReadOnly(const DeviceImage& image);
void recordBarriers(const vk::raii::CommandBuffer& commands, std::span<const vk::ImageMemoryBarrier2> images);

vk::RenderingAttachmentInfo clearedColor(const DeviceImage& image, const std::array<float, 4>& rgba);
vk::RenderingAttachmentInfo clearedDepth(const DeviceImage& image, vk::AttachmentStoreOp store);

// Negative height: NDC y = +1 (up, lighting::CameraView) lands on framebuffer
// row 0, the top of the image, and the meshes' counter-clockwise front faces
// stay counter-clockwise (raster_translation.h). Every pass uses it, so a
// pixel is the same texel of every target.
void setFlippedViewport(const vk::raii::CommandBuffer& commands, vk::Extent2D extent);

struct SceneObjectsPass {
  std::span<const vk::RenderingAttachmentInfo> colors;  // empty for a depth-only pass
  vk::RenderingAttachmentInfo depth;
  vk::Extent2D extent;
  vk::Pipeline pipeline;
  vk::PipelineLayout layout;
  // Binds set 0 with `object`'s dynamic offsets.
  std::function<void(const vk::raii::CommandBuffer&, std::size_t object)> bindUniforms;
  // Set 1, bound for every object, maps or not (the fragment stage declares
  // it); null for a pass whose shaders read no maps.
  const SceneBakedTextures* maps = nullptr;
  // The camera's passes flip (setFlippedViewport); a shadow map's does not:
  // its texel row 0 is map coordinate mv near 0, NDC y = -1.
  bool flipViewport = true;
};

// Begins rendering, draws every object of `geometry` with `pass`, ends.
void recordSceneObjectsPass(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry,
                            const SceneObjectsPass& pass);

}  // namespace backends::vulkan
