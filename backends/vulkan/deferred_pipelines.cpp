#include "backends/vulkan/deferred_pipelines.h"

#include "backends/vulkan/forward_pipeline.h"
#include "backends/vulkan/gbuffer_targets.h"
#include "backends/vulkan/raster_translation.h"
#include "backends/vulkan/scene_uniforms.h"
#include "lighting/gpu_packing.h"
#include "shaders/embedded_spirv.h"
#include "shaders/gbuffer_textures.h"

#include <array>
#include <vector>

namespace backends::vulkan {

DeferredPipelines::DeferredPipelines(const VulkanDevice& device, const PipelineCacheFile& cache,
                                     const vk::raii::DescriptorSetLayout& mapsSetLayout,
                                     const vk::raii::DescriptorSetLayout& lightTextureSetLayout)
    : builder_(device, cache),
      gbufferStages_(device.device, shaders::Stage::ForwardVertex, shaders::Stage::GbufferFragment),
      lightStages_(device.device, shaders::Stage::DeferredLightVertex, shaders::Stage::DeferredLightFragment),
      compositeStages_(device.device, shaders::Stage::DeferredCompositeVertex,
                       shaders::Stage::DeferredCompositeFragment) {
  // Set 0: the scene's uniforms as forward has them, the light block of each
  // light draw and the deferred frame block. Set 2: the G-buffer and the
  // light buffer.
  const auto stages = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
  const std::array<vk::DescriptorSetLayoutBinding, 2> scene = SceneUniforms::layoutBindings();
  const std::array<vk::DescriptorSetLayoutBinding, 4> uniforms{{
      scene[0],
      scene[1],
      {.binding = shaders::binding::kDeferredLightBlock.binding,
       .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .descriptorCount = 1, .stageFlags = stages},
      {.binding = shaders::binding::kDeferredFrameBlock.binding, .descriptorType = vk::DescriptorType::eUniformBuffer,
       .descriptorCount = 1, .stageFlags = stages},
  }};
  uniformsSetLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = uniforms.size(), .pBindings = uniforms.data()});
  std::array<vk::DescriptorSetLayoutBinding, kGBufferImageCount + 1> textures;
  for (std::uint32_t t = 0; t < textures.size(); ++t)
    textures[t] = {.binding = t < kGBufferImageCount ? shaders::kGbufferTextures[t].binding()
                                                     : shaders::binding::kLightBuffer.binding(),
                   .descriptorType = vk::DescriptorType::eCombinedImageSampler,
                   .descriptorCount = 1,
                   .stageFlags = vk::ShaderStageFlagBits::eFragment};
  texturesSetLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = textures.size(), .pBindings = textures.data()});
  const std::array<vk::DescriptorSetLayout, 4> setLayouts{*uniformsSetLayout_, *mapsSetLayout, *texturesSetLayout_,
                                                          *lightTextureSetLayout};
  layout_ = vk::raii::PipelineLayout(
      device.device, vk::PipelineLayoutCreateInfo{.setLayoutCount = setLayouts.size(), .pSetLayouts = setLayouts.data()});
}

// SPEC 1, as forward: the scene's objects are opaque surfaces.
const vk::raii::Pipeline& DeferredPipelines::gbuffer(const shaders::ConstantValues& constants) {
  return builder_.findOrCreate(gbuffer_, constants, [&] {
    return builder_.buildSceneObjects(layout_, gbufferStages_, constants,
                                      std::vector<vk::Format>(kGBufferImageCount, kGBufferFormat));
  });
}

const vk::raii::Pipeline& DeferredPipelines::light(const shaders::ConstantValues& constants,
                                                   const lighting::RasterState& raster,
                                                   lighting::DeferredBuffer buffer) {
  return builder_.findOrCreate(light_, std::tuple(constants, raster, buffer),
                               [&] { return createLight(constants, raster, buffer); });
}

const vk::raii::Pipeline& DeferredPipelines::composite(const shaders::ConstantValues& constants) {
  return builder_.findOrCreate(composite_, constants, [&] { return createComposite(constants); });
}

vk::raii::Pipeline DeferredPipelines::createLight(const shaders::ConstantValues& constants,
                                                  const lighting::RasterState& raster,
                                                  lighting::DeferredBuffer buffer) const {
  // lighting::LightVolume vertices: one vec4 each (GpuVec4).
  const vk::VertexInputBindingDescription binding{.binding = 0, .stride = sizeof(lighting::GpuVec4),
                                                  .inputRate = vk::VertexInputRate::eVertex};
  const vk::VertexInputAttributeDescription attribute{.location = 0, .binding = 0,
                                                      .format = vk::Format::eR32G32B32A32Sfloat, .offset = 0};
  const vk::PipelineVertexInputStateCreateInfo vertexInput{.vertexBindingDescriptionCount = 1,
                                                           .pVertexBindingDescriptions = &binding,
                                                           .vertexAttributeDescriptionCount = 1,
                                                           .pVertexAttributeDescriptions = &attribute};
  const PassPipelineState pass{
      .vertexInput = &vertexInput,
      .raster = raster,
      .blend = {blendedAttachment(lighting::lightBufferState(buffer).blend)},
      .colorFormats = {lightBufferFormat(buffer)},
      .depthFormat = kDepthFormat,
  };
  return builder_.build(layout_, lightStages_, constants, pass);
}

vk::raii::Pipeline DeferredPipelines::createComposite(const shaders::ConstantValues& constants) const {
  // The triangle comes from gl_VertexIndex: no vertex input.
  const vk::PipelineVertexInputStateCreateInfo vertexInput{};
  // No depth attachment: every pixel is written once.
  const PassPipelineState pass{
      .vertexInput = &vertexInput,
      .raster = {lighting::CullMode::None, lighting::DepthCompare::Always, false, false},
      .blend = {unblendedAttachment()},
      .colorFormats = {kColorFormat},
  };
  return builder_.build(layout_, compositeStages_, constants, pass);
}

}  // namespace backends::vulkan
