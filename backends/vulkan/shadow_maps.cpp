#include "backends/vulkan/shadow_maps.h"

#include "backends/aligned_stride.h"
#include "backends/backend.h"
#include "backends/vulkan/descriptor_set_indices.h"
#include "backends/vulkan/forward_pipeline.h"
#include "backends/vulkan/raster_translation.h"
#include "backends/vulkan/scene_pass.h"
#include "shaders/embedded_spirv.h"

#include <cstring>
#include <string>

namespace backends::vulkan {
namespace {

constexpr int k2dSlots = lighting::kMaxShadowMaps;
constexpr vk::ImageLayout kSampledDepth = vk::ImageLayout::eDepthStencilReadOnlyOptimal;
constexpr vk::PipelineStageFlags2 kDepthTests =
    vk::PipelineStageFlagBits2::eEarlyFragmentTests | vk::PipelineStageFlagBits2::eLateFragmentTests;
// The most passes a frame records: every 2D slot and every cube face.
constexpr std::size_t kMostViews = lighting::kMaxShadowMaps + 6 * lighting::kMaxShadowCubes;

vk::raii::Sampler compareSampler(const vk::raii::Device& device, vk::Filter filter, vk::CompareOp compare) {
  return vk::raii::Sampler(device, vk::SamplerCreateInfo{.magFilter = filter,
                                                         .minFilter = filter,
                                                         .mipmapMode = vk::SamplerMipmapMode::eNearest,
                                                         .addressModeU = vk::SamplerAddressMode::eClampToEdge,
                                                         .addressModeV = vk::SamplerAddressMode::eClampToEdge,
                                                         .addressModeW = vk::SamplerAddressMode::eClampToEdge,
                                                         .mipLodBias = 0.0f,
                                                         .anisotropyEnable = VK_FALSE,
                                                         .compareEnable = VK_TRUE,
                                                         .compareOp = compare,
                                                         .minLod = 0.0f,
                                                         .maxLod = 0.0f,
                                                         .unnormalizedCoordinates = VK_FALSE});
}

vk::ImageMemoryBarrier2 depthBarrier(const DeviceImage& image, vk::PipelineStageFlags2 srcStage,
                                     vk::AccessFlags2 srcAccess, vk::ImageLayout from, vk::PipelineStageFlags2 dstStage,
                                     vk::AccessFlags2 dstAccess, vk::ImageLayout to) {
  return {.srcStageMask = srcStage,
          .srcAccessMask = srcAccess,
          .dstStageMask = dstStage,
          .dstAccessMask = dstAccess,
          .oldLayout = from,
          .newLayout = to,
          .image = *image.image,
          .subresourceRange = {vk::ImageAspectFlagBits::eDepth, 0, 1, 0, image.layers}};
}

vk::RenderingAttachmentInfo clearedDepthView(vk::ImageView view) {
  return {.imageView = view,
          .imageLayout = vk::ImageLayout::eDepthAttachmentOptimal,
          .loadOp = vk::AttachmentLoadOp::eClear,
          .storeOp = vk::AttachmentStoreOp::eStore,
          .clearValue = vk::ClearDepthStencilValue{lighting::kClearDepth, 0}};
}

}  // namespace

ShadowMaps::ShadowMaps(const VulkanDevice& device, const PipelineCacheFile& cache, vk::DescriptorSet set,
                       shaders::Mutant mutant)
    : device_(device),
      block_(device, sizeof(lighting::GpuShadowBlock), vk::BufferUsageFlagBits::eUniformBuffer),
      set_(set),
      stages_(device.device, shaders::Stage::ShadowCasterVertex, shaders::Stage::ShadowCasterFragment),
      viewStride_(alignedStride(sizeof(lighting::GpuShadowPassBlock), device.limits.minUniformBufferOffsetAlignment)),
      viewBlocks_(device, viewStride_ * kMostViews, vk::BufferUsageFlagBits::eUniformBuffer) {
  // SPEC 3.9's compare, decided beside the raster state (lighting/raster_state.h).
  const vk::CompareOp compare = toVulkan(shaders::shadowLookupCompare(mutant));
  // A map is rendered as a depth attachment and sampled with a compare.
  // Filtering the compares linearly (bilinear, tent3x3) needs no
  // FILTER_LINEAR feature: Vulkan asks for that only of samplers without a
  // compare (VUID-vkCmdDraw-magFilter-04553); lavapipe, which lacks it on
  // D32_SFLOAT, filters compares all the same.
  const vk::FormatFeatureFlags features = device.physical.getFormatProperties(kDepthFormat).optimalTilingFeatures;
  const auto needed = vk::FormatFeatureFlagBits::eSampledImage | vk::FormatFeatureFlagBits::eDepthStencilAttachment;
  if ((features & needed) != needed)
    throw NotSupportedError(device.info.name + " cannot render and sample D32_SFLOAT depth (shadow maps)");
  nearest_ = compareSampler(device.device, vk::Filter::eNearest, compare);
  linear_ = compareSampler(device.device, vk::Filter::eLinear, compare);
  for (int s = 0; s < lighting::kGpuShadowSlots; ++s) ensureSlot(slots_[s], 1, s >= k2dSlots);

  const auto vertex = vk::ShaderStageFlagBits::eVertex;
  static_assert(kShadowPassSetIndex == shaders::binding::kObjectBlock.set);  // one set, the pass's only one
  const std::array<vk::DescriptorSetLayoutBinding, 2> bindings{{
      {.binding = shaders::binding::kShadowPassBlock.binding,
       .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .descriptorCount = 1, .stageFlags = vertex},
      {.binding = shaders::binding::kObjectBlock.binding, .descriptorType = vk::DescriptorType::eUniformBufferDynamic,
       .descriptorCount = 1, .stageFlags = vertex},
  }};
  passSetLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = bindings.size(), .pBindings = bindings.data()});
  passLayout_ = vk::raii::PipelineLayout(
      device.device, vk::PipelineLayoutCreateInfo{.setLayoutCount = 1, .pSetLayouts = &*passSetLayout_});
  // The scene's vertex buffer, position only: the caster reads no normal
  // (an unread attribute is a validation performance warning).
  const SceneVertexInput sceneVertices;
  const vk::PipelineVertexInputStateCreateInfo vertexInput{.vertexBindingDescriptionCount = 1,
                                                           .pVertexBindingDescriptions = &sceneVertices.binding,
                                                           .vertexAttributeDescriptionCount = 1,
                                                           .pVertexAttributeDescriptions = &sceneVertices.attributes[0]};
  const PassPipelineState pass{.vertexInput = &vertexInput,
                               .raster = lighting::kShadowCasterState,
                               .blend = {},
                               .colorFormats = {},
                               .depthFormat = kDepthFormat};
  // The caster reads no specialization constant; the defaults serve.
  pipeline_ = PipelineBuilder(device, cache).build(passLayout_, stages_, shaders::ConstantValues{}, pass);
  cache.save();
  const std::array<vk::DescriptorPoolSize, 1> perSet{{{vk::DescriptorType::eUniformBufferDynamic, 2}}};
  passSets_ = DescriptorSets(device.device, passSetLayout_, perSet, 1);
  const lighting::GpuShadowBlock empty{};
  block_.write(std::span(&empty, 1));
  writeSet(nullptr);
}

void ShadowMaps::ensureSlot(SlotImage& slot, int resolution, bool cube) {
  if (slot.image && slot.resolution == resolution) return;
  const std::uint32_t limit = cube ? device_.limits.maxImageDimensionCube : device_.limits.maxImageDimension2D;
  if (std::uint32_t(resolution) > limit)
    throw NotSupportedError(device_.info.name + " cannot hold a " + std::to_string(resolution) + " x " +
                            std::to_string(resolution) + (cube ? " cube" : "") + " shadow map (" +
                            (cube ? "maxImageDimensionCube " : "maxImageDimension2D ") + std::to_string(limit) + ")");
  slot.faces.clear();
  slot.image.reset();
  const auto usage = vk::ImageUsageFlagBits::eDepthStencilAttachment | vk::ImageUsageFlagBits::eSampled |
                     vk::ImageUsageFlagBits::eTransferSrc;
  slot.image.emplace(device_, kDepthFormat, vk::Extent2D{std::uint32_t(resolution), std::uint32_t(resolution)}, usage,
                     vk::ImageAspectFlagBits::eDepth, cube ? ImageShape::Cube : ImageShape::Flat);
  if (cube)
    for (std::uint32_t face = 0; face < 6; ++face)
      slot.faces.emplace_back(device_.device,
                              vk::ImageViewCreateInfo{.image = *slot.image->image,
                                                      .viewType = vk::ImageViewType::e2D,
                                                      .format = kDepthFormat,
                                                      .subresourceRange = {vk::ImageAspectFlagBits::eDepth, 0, 1,
                                                                           face, 1}});
  slot.resolution = resolution;
  slot.cube = cube;
  slot.ready = false;
}

void ShadowMaps::update(const lighting::Frame& frame) {
  const lighting::ShadowSlots& shadows = frame.shadows;
  for (int s = 0; s < lighting::kGpuShadowSlots; ++s) {
    const bool cube = s >= k2dSlots;
    const std::vector<lighting::ShadowProjection>& list = cube ? shadows.cubes : shadows.maps;
    const int index = cube ? s - k2dSlots : s;
    const bool used = index < int(list.size());
    ensureSlot(slots_[s], used ? list[index].spec.resolution : 1, cube);
  }
  views_ = lighting::shadowPassViews(frame);
  for (std::size_t v = 0; v < views_.size(); ++v) {
    const lighting::GpuShadowPassBlock block =
        lighting::packShadowPassBlock(views_[v], device_.info.subPixelPrecisionBits);
    viewBlocks_.write(std::span(&block, 1), v * viewStride_);
  }
  const std::size_t objectCount = frame.scene().objects.size();
  if (!objects_ || objects_->objectCapacity() < objectCount) {
    objects_.reset();
    objects_.emplace(device_, objectCount);
    const vk::DescriptorBufferInfo viewInfo{*viewBlocks_.buffer, 0, sizeof(lighting::GpuShadowPassBlock)};
    const vk::DescriptorSet passSet = *passSets_.sets.front();
    const std::array<vk::WriteDescriptorSet, 2> writes{
        {{.dstSet = passSet, .dstBinding = shaders::binding::kShadowPassBlock.binding, .descriptorCount = 1,
          .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .pBufferInfo = &viewInfo},
         objects_->descriptorWrites(passSet)[1]}};
    device_.device.updateDescriptorSets(writes, {});
  }
  if (!views_.empty()) objects_->write(frame);
  const lighting::GpuShadowBlock block = lighting::packShadowBlock(frame);
  block_.write(std::span(&block, 1));
  writeSet(&frame);
}

void ShadowMaps::writeSet(const lighting::Frame* frame) {
  std::array<vk::DescriptorImageInfo, lighting::kGpuShadowSlots> images;
  for (int s = 0; s < lighting::kGpuShadowSlots; ++s)
    images[s] = {.sampler = *nearest_, .imageView = *slots_[s].image->view, .imageLayout = kSampledDepth};
  if (frame) {
    const lighting::ShadowSlots& shadows = frame->shadows;
    for (std::size_t m = 0; m < shadows.maps.size(); ++m)
      if (shadows.maps[m].spec.filter != lighting::ShadowFilter::Hard) images[m].sampler = *linear_;
    for (std::size_t c = 0; c < shadows.cubes.size(); ++c)
      if (shadows.cubes[c].spec.filter != lighting::ShadowFilter::Hard) images[k2dSlots + c].sampler = *linear_;
  }
  const vk::DescriptorBufferInfo blockInfo{*block_.buffer, 0, sizeof(lighting::GpuShadowBlock)};
  std::array<vk::WriteDescriptorSet, 1 + lighting::kGpuShadowSlots> writes;
  writes[0] = {.dstSet = set_, .dstBinding = shaders::binding::kShadowBlock.binding, .descriptorCount = 1,
               .descriptorType = vk::DescriptorType::eUniformBuffer, .pBufferInfo = &blockInfo};
  for (int s = 0; s < lighting::kGpuShadowSlots; ++s)
    writes[1 + s] = {.dstSet = set_,
                     .dstBinding = s < k2dSlots ? shaders::binding::kShadowMap.binding(s)
                                                : shaders::binding::kShadowCube.binding(s - k2dSlots),
                     .descriptorCount = 1,
                     .descriptorType = vk::DescriptorType::eCombinedImageSampler, .pImageInfo = &images[s]};
  device_.device.updateDescriptorSets(writes, {});
}

void ShadowMaps::record(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry) {
  // Which slots this frame draws; the others keep what they hold (a stand-in
  // of 1, or a map no light of this frame reads), cleared once when made.
  std::array<bool, lighting::kGpuShadowSlots> drawn{};
  for (const lighting::ShadowPassView& v : views_) drawn[v.slot] = true;
  std::vector<vk::ImageMemoryBarrier2> toAttachment, toSampled;
  for (int s = 0; s < lighting::kGpuShadowSlots; ++s) {
    if (!drawn[s] && slots_[s].ready) continue;
    const DeviceImage& image = *slots_[s].image;
    toAttachment.push_back(depthBarrier(image, vk::PipelineStageFlagBits2::eAllCommands,
                                        vk::AccessFlagBits2::eMemoryWrite, vk::ImageLayout::eUndefined, kDepthTests,
                                        vk::AccessFlagBits2::eDepthStencilAttachmentRead |
                                            vk::AccessFlagBits2::eDepthStencilAttachmentWrite,
                                        vk::ImageLayout::eDepthAttachmentOptimal));
    toSampled.push_back(depthBarrier(image, kDepthTests, vk::AccessFlagBits2::eDepthStencilAttachmentWrite,
                                     vk::ImageLayout::eDepthAttachmentOptimal,
                                     vk::PipelineStageFlagBits2::eFragmentShader,
                                     vk::AccessFlagBits2::eShaderSampledRead, kSampledDepth));
  }
  if (toAttachment.empty()) return;  // a frame without shadows, every slot ready: nothing to do
  recordBarriers(commands, toAttachment);
  const vk::DescriptorSet passSet = *passSets_.sets.front();
  for (int s = 0; s < lighting::kGpuShadowSlots; ++s) {
    SlotImage& slot = slots_[s];
    if (!drawn[s] && slot.ready) continue;
    const std::uint32_t n = std::uint32_t(slot.resolution);
    for (std::uint32_t layer = 0; layer < slot.image->layers; ++layer) {
      const vk::ImageView target = slot.cube ? *slot.faces[layer] : *slot.image->view;
      std::optional<std::size_t> view;
      for (std::size_t v = 0; v < views_.size(); ++v)
        if (views_[v].slot == s && views_[v].face == int(layer)) view = v;
      const vk::RenderingAttachmentInfo depth = clearedDepthView(target);
      if (!view) {
        // A slot no light of this frame has: a map of 1, never read (its kind is None).
        commands.beginRendering(vk::RenderingInfo{.renderArea = {{0, 0}, {n, n}}, .layerCount = 1,
                                                  .pDepthAttachment = &depth});
        commands.endRendering();
        continue;
      }
      const std::uint32_t viewOffset = std::uint32_t(*view * viewStride_);
      recordSceneObjectsPass(commands, geometry,
                             {.colors = {},
                              .depth = depth,
                              .extent = {n, n},
                              .pipeline = *pipeline_,
                              .layout = *passLayout_,
                              .bindUniforms =
                                  [&](const vk::raii::CommandBuffer& cb, std::size_t object) {
                                    cb.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *passLayout_, kShadowPassSetIndex, {passSet},
                                                          {viewOffset, objects_->objectOffset(object)});
                                  },
                              .maps = nullptr,
                              // Texel row 0 is mv = 0.5 / N: NDC y = -1 on framebuffer row 0.
                              .flipViewport = false});
    }
    slot.ready = true;  // in the sampled layout once the submission completes (draw waits for it)
  }
  recordBarriers(commands, toSampled);
}

void ShadowMaps::recordReadback(const vk::raii::CommandBuffer& commands) {
  vk::DeviceSize total = 0;
  for (const lighting::ShadowPassView& v : views_) total += vk::DeviceSize(v.resolution) * v.resolution * sizeof(float);
  if (!staging_ || staging_->size < total) {
    staging_.reset();
    staging_.emplace(device_, std::max<vk::DeviceSize>(total, 4), vk::BufferUsageFlagBits::eTransferDst);
  }
  std::vector<vk::ImageMemoryBarrier2> toTransfer, back;
  for (const SlotImage& slot : slots_) {
    toTransfer.push_back(depthBarrier(*slot.image, vk::PipelineStageFlagBits2::eFragmentShader,
                                      vk::AccessFlagBits2::eShaderSampledRead, kSampledDepth,
                                      vk::PipelineStageFlagBits2::eCopy, vk::AccessFlagBits2::eTransferRead,
                                      vk::ImageLayout::eTransferSrcOptimal));
    back.push_back(depthBarrier(*slot.image, vk::PipelineStageFlagBits2::eCopy, vk::AccessFlagBits2::eTransferRead,
                                vk::ImageLayout::eTransferSrcOptimal, vk::PipelineStageFlagBits2::eFragmentShader,
                                vk::AccessFlagBits2::eShaderSampledRead, kSampledDepth));
  }
  recordBarriers(commands, toTransfer);
  vk::DeviceSize offset = 0;
  for (const lighting::ShadowPassView& v : views_) {
    const std::uint32_t n = std::uint32_t(v.resolution);
    const vk::BufferImageCopy region{.bufferOffset = offset,
                                     .imageSubresource = {vk::ImageAspectFlagBits::eDepth, 0, std::uint32_t(v.face), 1},
                                     .imageExtent = {n, n, 1}};
    commands.copyImageToBuffer(*slots_[v.slot].image->image, vk::ImageLayout::eTransferSrcOptimal,
                               *staging_->buffer, region);
    offset += vk::DeviceSize(n) * n * sizeof(float);
  }
  recordBarriers(commands, back);
  const vk::BufferMemoryBarrier2 toHost{.srcStageMask = vk::PipelineStageFlagBits2::eCopy,
                                        .srcAccessMask = vk::AccessFlagBits2::eTransferWrite,
                                        .dstStageMask = vk::PipelineStageFlagBits2::eHost,
                                        .dstAccessMask = vk::AccessFlagBits2::eHostRead,
                                        .buffer = *staging_->buffer,
                                        .size = VK_WHOLE_SIZE};
  commands.pipelineBarrier2(vk::DependencyInfo{.bufferMemoryBarrierCount = 1, .pBufferMemoryBarriers = &toHost});
}

std::vector<imaging::Image> ShadowMaps::readbackImages() const {
  std::vector<imaging::Image> images;
  const float* texels = static_cast<const float*>(staging_->mapped);
  for (const lighting::ShadowPassView& v : views_) {
    imaging::Image image(v.resolution, v.resolution, 1);
    std::memcpy(image.pixels.data(), texels, image.pixels.size() * sizeof(float));
    texels += image.pixels.size();
    images.push_back(std::move(image));
  }
  return images;
}

}  // namespace backends::vulkan
