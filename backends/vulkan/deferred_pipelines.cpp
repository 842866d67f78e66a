#include "backends/vulkan/deferred_pipelines.h"

#include "backends/vulkan/forward_pipeline.h"
#include "backends/vulkan/gbuffer_targets.h"
#include "backends/vulkan/scene_geometry.h"
#include "lighting/gpu_packing.h"
#include "shaders/embedded_spirv.h"

#include <array>
#include <span>
#include <vector>

namespace backends::vulkan {
namespace {

constexpr auto kAllChannels = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                              vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA;

vk::raii::ShaderModule shaderModule(const vk::raii::Device& device, std::span<const std::uint32_t> spirv) {
  return vk::raii::ShaderModule(device, vk::ShaderModuleCreateInfo{.codeSize = spirv.size_bytes(), .pCode = spirv.data()});
}

// Every specialization constant of features.glsl at its id; a stage ignores
// the ids it does not declare.
struct Specialization {
  explicit Specialization(const shaders::ConstantValues& constants) {
    for (std::uint32_t id = 0; id < shaders::kConstantCount; ++id)
      entries[id] = vk::SpecializationMapEntry{.constantID = id, .offset = id * std::uint32_t(sizeof(std::int32_t)),
                                               .size = sizeof(std::int32_t)};
    info = vk::SpecializationInfo{.mapEntryCount = std::uint32_t(entries.size()), .pMapEntries = entries.data(),
                                  .dataSize = sizeof(constants), .pData = constants.data()};
  }
  Specialization(const Specialization&) = delete;  // info points into entries

  std::array<vk::SpecializationMapEntry, shaders::kConstantCount> entries;
  vk::SpecializationInfo info;
};

// The state that differs between the three passes; the rest is shared.
struct PassState {
  vk::ShaderModule vertex;
  vk::ShaderModule fragment;
  const vk::PipelineVertexInputStateCreateInfo* vertexInput;
  vk::PipelineRasterizationStateCreateInfo rasterization;
  vk::PipelineDepthStencilStateCreateInfo depth;
  std::vector<vk::PipelineColorBlendAttachmentState> blend;  // one per colour attachment
  std::vector<vk::Format> colorFormats;
  vk::Format depthFormat = vk::Format::eUndefined;
};

vk::raii::Pipeline buildPipeline(const VulkanDevice& device, const PipelineCacheFile& cache,
                                 const vk::raii::PipelineLayout& layout, const shaders::ConstantValues& constants,
                                 const PassState& pass) {
  const Specialization specialization(constants);
  const std::array<vk::PipelineShaderStageCreateInfo, 2> stages{{
      {.stage = vk::ShaderStageFlagBits::eVertex, .module = pass.vertex, .pName = "main",
       .pSpecializationInfo = &specialization.info},
      {.stage = vk::ShaderStageFlagBits::eFragment, .module = pass.fragment, .pName = "main",
       .pSpecializationInfo = &specialization.info},
  }};
  const vk::PipelineInputAssemblyStateCreateInfo inputAssembly{.topology = vk::PrimitiveTopology::eTriangleList};
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  const vk::PipelineColorBlendStateCreateInfo blend{.attachmentCount = std::uint32_t(pass.blend.size()),
                                                    .pAttachments = pass.blend.data()};
  const std::array<vk::DynamicState, 2> dynamicStates{vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = dynamicStates.size(),
                                                   .pDynamicStates = dynamicStates.data()};
  const vk::PipelineRenderingCreateInfo rendering{.colorAttachmentCount = std::uint32_t(pass.colorFormats.size()),
                                                  .pColorAttachmentFormats = pass.colorFormats.data(),
                                                  .depthAttachmentFormat = pass.depthFormat};
  const vk::GraphicsPipelineCreateInfo info{.pNext = &rendering,
                                            .stageCount = stages.size(),
                                            .pStages = stages.data(),
                                            .pVertexInputState = pass.vertexInput,
                                            .pInputAssemblyState = &inputAssembly,
                                            .pViewportState = &viewport,
                                            .pRasterizationState = &pass.rasterization,
                                            .pMultisampleState = &multisample,
                                            .pDepthStencilState = &pass.depth,
                                            .pColorBlendState = &blend,
                                            .pDynamicState = &dynamic,
                                            .layout = *layout};
  return vk::raii::Pipeline(device.device, cache.cache(), info);
}

// The viewport is flipped (negative height) as in the forward pass, which
// keeps the meshes' counter-clockwise front faces counter-clockwise
// (forward_pipeline.cpp).
vk::PipelineRasterizationStateCreateInfo rasterization(vk::CullModeFlags cull, bool depthClamp = false) {
  return {.depthClampEnable = depthClamp ? VK_TRUE : VK_FALSE,
          .polygonMode = vk::PolygonMode::eFill,
          .cullMode = cull,
          .frontFace = vk::FrontFace::eCounterClockwise,
          .lineWidth = 1.0f};
}

// The pipeline under `key`, created (and the cache file saved) the first time.
template <class Map, class Key, class Create>
const vk::raii::Pipeline& findOrCreate(Map& map, const Key& key, Create&& create, const PipelineCacheFile& cache) {
  auto found = map.find(key);
  if (found != map.end()) return found->second;
  auto [inserted, _] = map.emplace(key, create());
  cache.save();
  return inserted->second;
}

}  // namespace

LightVolumeDraw lightVolumeDraw(lighting::LightVolumeShape shape, shaders::Mutant mutant) {
  switch (shape) {
    case lighting::LightVolumeShape::FullScreen: return LightVolumeDraw::FullScreen;
    case lighting::LightVolumeShape::Icosphere:
      return mutant == shaders::Mutant::PointVolumeOutsideOnly ? LightVolumeDraw::FrontFacesBeforeSurface
                                                               : LightVolumeDraw::BackFacesBehindSurface;
    case lighting::LightVolumeShape::Pyramid: return LightVolumeDraw::BackFacesBehindSurface;
  }
  return LightVolumeDraw::BackFacesBehindSurface;
}

DeferredPipelines::DeferredPipelines(const VulkanDevice& device, const PipelineCacheFile& cache,
                                     const vk::raii::DescriptorSetLayout& mapsSetLayout)
    : device_(device), cache_(cache) {
  const auto stages = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
  const std::array<vk::DescriptorSetLayoutBinding, 4> uniforms{{
      {.binding = 0, .descriptorType = vk::DescriptorType::eUniformBuffer, .descriptorCount = 1, .stageFlags = stages},
      {.binding = 1, .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .descriptorCount = 1, .stageFlags = stages},
      {.binding = 2, .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .descriptorCount = 1, .stageFlags = stages},
      {.binding = 3, .descriptorType = vk::DescriptorType::eUniformBuffer, .descriptorCount = 1, .stageFlags = stages},
  }};
  uniformsSetLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = uniforms.size(), .pBindings = uniforms.data()});
  std::array<vk::DescriptorSetLayoutBinding, kGBufferImageCount + 1> textures;
  for (std::uint32_t b = 0; b < textures.size(); ++b)
    textures[b] = {.binding = b, .descriptorType = vk::DescriptorType::eCombinedImageSampler, .descriptorCount = 1,
                   .stageFlags = vk::ShaderStageFlagBits::eFragment};
  texturesSetLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = textures.size(), .pBindings = textures.data()});
  const std::array<vk::DescriptorSetLayout, 3> setLayouts{*uniformsSetLayout_, *mapsSetLayout, *texturesSetLayout_};
  layout_ = vk::raii::PipelineLayout(
      device.device, vk::PipelineLayoutCreateInfo{.setLayoutCount = setLayouts.size(), .pSetLayouts = setLayouts.data()});
  forwardVertex_ = shaderModule(device.device, shaders::forwardVertexSpirv());
  gbufferFragment_ = shaderModule(device.device, shaders::gbufferFragmentSpirv());
  lightVertex_ = shaderModule(device.device, shaders::deferredLightVertexSpirv());
  lightFragment_ = shaderModule(device.device, shaders::deferredLightFragmentSpirv());
  compositeVertex_ = shaderModule(device.device, shaders::deferredCompositeVertexSpirv());
  compositeFragment_ = shaderModule(device.device, shaders::deferredCompositeFragmentSpirv());
}

const vk::raii::Pipeline& DeferredPipelines::gbuffer(const shaders::ConstantValues& constants) {
  return findOrCreate(gbuffer_, constants, [&] { return createGBuffer(constants); }, cache_);
}

const vk::raii::Pipeline& DeferredPipelines::light(const shaders::ConstantValues& constants, LightVolumeDraw draw,
                                                   vk::Format lightBufferFormat) {
  return findOrCreate(light_, std::tuple(constants, draw, lightBufferFormat),
                      [&] { return createLight(constants, draw, lightBufferFormat); }, cache_);
}

const vk::raii::Pipeline& DeferredPipelines::composite(const shaders::ConstantValues& constants) {
  return findOrCreate(composite_, constants, [&] { return createComposite(constants); }, cache_);
}

vk::raii::Pipeline DeferredPipelines::createGBuffer(const shaders::ConstantValues& constants) const {
  // forward.vert's inputs, as the forward pipeline feeds them.
  const SceneVertexInput sceneVertices;
  const vk::PipelineVertexInputStateCreateInfo vertexInput = sceneVertices.state();
  PassState pass{
      .vertex = *forwardVertex_,
      .fragment = *gbufferFragment_,
      .vertexInput = &vertexInput,
      .rasterization = rasterization(vk::CullModeFlagBits::eBack),
      .depth = {.depthTestEnable = VK_TRUE, .depthWriteEnable = VK_TRUE, .depthCompareOp = vk::CompareOp::eLess},
      .blend = std::vector<vk::PipelineColorBlendAttachmentState>(
          kGBufferImageCount, {.blendEnable = VK_FALSE, .colorWriteMask = kAllChannels}),
      .colorFormats = std::vector<vk::Format>(kGBufferImageCount, kGBufferFormat),
      .depthFormat = kDepthFormat,
  };
  return buildPipeline(device_, cache_, layout_, constants, pass);
}

vk::raii::Pipeline DeferredPipelines::createLight(const shaders::ConstantValues& constants, LightVolumeDraw draw,
                                                  vk::Format format) const {
  // lighting::LightVolume vertices: one vec4 each (GpuVec4).
  const vk::VertexInputBindingDescription binding{.binding = 0, .stride = sizeof(lighting::GpuVec4),
                                                  .inputRate = vk::VertexInputRate::eVertex};
  const vk::VertexInputAttributeDescription attribute{.location = 0, .binding = 0,
                                                      .format = vk::Format::eR32G32B32A32Sfloat, .offset = 0};
  const vk::PipelineVertexInputStateCreateInfo vertexInput{.vertexBindingDescriptionCount = 1,
                                                           .pVertexBindingDescriptions = &binding,
                                                           .vertexAttributeDescriptionCount = 1,
                                                           .pVertexAttributeDescriptions = &attribute};
  // hdr: the buffer sums c (ONE, ONE from a clear of 0); ldr8: it multiplies
  // exp2(-c) (DST_COLOR, ZERO from a clear of 1).
  const bool multiply = format == lightBufferFormat(lighting::DeferredBuffer::Ldr8);
  const vk::BlendFactor source = multiply ? vk::BlendFactor::eDstColor : vk::BlendFactor::eOne;
  const vk::BlendFactor destination = multiply ? vk::BlendFactor::eZero : vk::BlendFactor::eOne;
  const vk::BlendFactor sourceAlpha = multiply ? vk::BlendFactor::eDstAlpha : vk::BlendFactor::eOne;
  const vk::PipelineColorBlendAttachmentState blend{.blendEnable = VK_TRUE,
                                                    .srcColorBlendFactor = source,
                                                    .dstColorBlendFactor = destination,
                                                    .colorBlendOp = vk::BlendOp::eAdd,
                                                    .srcAlphaBlendFactor = sourceAlpha,
                                                    .dstAlphaBlendFactor = destination,
                                                    .alphaBlendOp = vk::BlendOp::eAdd,
                                                    .colorWriteMask = kAllChannels};
  // The G-buffer depth is attached read-only: test, never write. Depth clamp
  // keeps a volume's back faces past the far plane instead of clipping them.
  vk::CullModeFlags cull = vk::CullModeFlagBits::eNone;
  vk::CompareOp test = vk::CompareOp::eAlways;
  switch (draw) {
    case LightVolumeDraw::FullScreen: break;
    case LightVolumeDraw::BackFacesBehindSurface:
      cull = vk::CullModeFlagBits::eFront;
      test = vk::CompareOp::eGreaterOrEqual;
      break;
    case LightVolumeDraw::FrontFacesBeforeSurface:
      cull = vk::CullModeFlagBits::eBack;
      test = vk::CompareOp::eLessOrEqual;
      break;
  }
  const PassState pass{
      .vertex = *lightVertex_,
      .fragment = *lightFragment_,
      .vertexInput = &vertexInput,
      .rasterization = rasterization(cull, draw != LightVolumeDraw::FullScreen && device_.depthClamp),
      .depth = {.depthTestEnable = VK_TRUE, .depthWriteEnable = VK_FALSE, .depthCompareOp = test},
      .blend = {blend},
      .colorFormats = {format},
      .depthFormat = kDepthFormat,
  };
  return buildPipeline(device_, cache_, layout_, constants, pass);
}

vk::raii::Pipeline DeferredPipelines::createComposite(const shaders::ConstantValues& constants) const {
  // The triangle comes from gl_VertexIndex: no vertex input.
  const vk::PipelineVertexInputStateCreateInfo vertexInput{};
  const PassState pass{
      .vertex = *compositeVertex_,
      .fragment = *compositeFragment_,
      .vertexInput = &vertexInput,
      .rasterization = rasterization(vk::CullModeFlagBits::eNone),
      .depth = {.depthTestEnable = VK_FALSE, .depthWriteEnable = VK_FALSE},
      .blend = {{.blendEnable = VK_FALSE, .colorWriteMask = kAllChannels}},
      .colorFormats = {kColorFormat},
  };
  return buildPipeline(device_, cache_, layout_, constants, pass);
}

}  // namespace backends::vulkan
