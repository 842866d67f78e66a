#include "backends/vulkan/forward_pipeline.h"

#include "backends/vulkan/baked_textures.h"
#include "backends/vulkan/scene_geometry.h"
#include "lighting/gpu_packing.h"
#include "shaders/embedded_spirv.h"

#include <array>

namespace backends::vulkan {
namespace {

vk::raii::ShaderModule shaderModule(const vk::raii::Device& device, std::span<const std::uint32_t> spirv) {
  return vk::raii::ShaderModule(device, vk::ShaderModuleCreateInfo{.codeSize = spirv.size_bytes(), .pCode = spirv.data()});
}

}  // namespace

ForwardPipelines::ForwardPipelines(const VulkanDevice& device, const PipelineCacheFile& cache)
    : device_(device), cache_(cache) {
  const auto stages = vk::ShaderStageFlagBits::eVertex | vk::ShaderStageFlagBits::eFragment;
  const std::array<vk::DescriptorSetLayoutBinding, 2> bindings{{
      {.binding = 0, .descriptorType = vk::DescriptorType::eUniformBuffer, .descriptorCount = 1, .stageFlags = stages},
      {.binding = 1, .descriptorType = vk::DescriptorType::eUniformBufferDynamic, .descriptorCount = 1, .stageFlags = stages},
  }};
  setLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = bindings.size(), .pBindings = bindings.data()});
  // Set 1 is in every pipeline's layout: the fragment stage's SPIR-V declares
  // the map samplers whatever the LIGHTMAP and SHADOW_MASK constants say.
  mapsSetLayout_ = createBakedMapsSetLayout(device.device);
  const std::array<vk::DescriptorSetLayout, 2> setLayouts{*setLayout_, *mapsSetLayout_};
  layout_ = vk::raii::PipelineLayout(
      device.device, vk::PipelineLayoutCreateInfo{.setLayoutCount = setLayouts.size(), .pSetLayouts = setLayouts.data()});
  vertex_ = shaderModule(device.device, shaders::forwardVertexSpirv());
  fragment_ = shaderModule(device.device, shaders::forwardFragmentSpirv());
}

const vk::raii::Pipeline& ForwardPipelines::pipeline(const shaders::ConstantValues& constants) {
  auto found = pipelines_.find(constants);
  if (found != pipelines_.end()) return found->second;
  auto [inserted, _] = pipelines_.emplace(constants, create(constants));
  cache_.save();
  return inserted->second;
}

vk::raii::Pipeline ForwardPipelines::create(const shaders::ConstantValues& constants) const {
  std::array<vk::SpecializationMapEntry, shaders::kConstantCount> entries;
  for (std::uint32_t id = 0; id < shaders::kConstantCount; ++id)
    entries[id] = vk::SpecializationMapEntry{.constantID = id, .offset = id * std::uint32_t(sizeof(std::int32_t)), .size = sizeof(std::int32_t)};
  const vk::SpecializationInfo specialization{.mapEntryCount = entries.size(), .pMapEntries = entries.data(),
                                              .dataSize = sizeof(constants), .pData = constants.data()};
  const std::array<vk::PipelineShaderStageCreateInfo, 2> stages{{
      {.stage = vk::ShaderStageFlagBits::eVertex, .module = *vertex_, .pName = "main", .pSpecializationInfo = &specialization},
      {.stage = vk::ShaderStageFlagBits::eFragment, .module = *fragment_, .pName = "main", .pSpecializationInfo = &specialization},
  }};

  const SceneVertexInput sceneVertices;
  const vk::PipelineVertexInputStateCreateInfo vertexInput = sceneVertices.state();
  const vk::PipelineInputAssemblyStateCreateInfo inputAssembly{.topology = vk::PrimitiveTopology::eTriangleList};
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  // SPEC 1: back faces culled, one sample at the pixel centre, depth LESS.
  // The viewport is flipped (negative height, vulkan_backend.cpp) so that NDC
  // y points up as in lighting::CameraView and the image is not mirrored;
  // Vulkan decides the winding in framebuffer space as the image shows it, so
  // the mesh's counter-clockwise front faces stay counter-clockwise.
  const vk::PipelineRasterizationStateCreateInfo rasterization{.polygonMode = vk::PolygonMode::eFill,
                                                               .cullMode = vk::CullModeFlagBits::eBack,
                                                               .frontFace = vk::FrontFace::eCounterClockwise,
                                                               .lineWidth = 1.0f};
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  const vk::PipelineDepthStencilStateCreateInfo depth{.depthTestEnable = VK_TRUE, .depthWriteEnable = VK_TRUE,
                                                      .depthCompareOp = vk::CompareOp::eLess};
  const vk::PipelineColorBlendAttachmentState blendAttachment{
      .blendEnable = VK_FALSE,
      .colorWriteMask = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                        vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA};
  const vk::PipelineColorBlendStateCreateInfo blend{.attachmentCount = 1, .pAttachments = &blendAttachment};
  const std::array<vk::DynamicState, 2> dynamicStates{vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = dynamicStates.size(),
                                                   .pDynamicStates = dynamicStates.data()};
  const vk::Format colorFormat = kColorFormat;
  const vk::PipelineRenderingCreateInfo rendering{.colorAttachmentCount = 1, .pColorAttachmentFormats = &colorFormat,
                                                  .depthAttachmentFormat = kDepthFormat};
  const vk::GraphicsPipelineCreateInfo info{.pNext = &rendering,
                                            .stageCount = stages.size(),
                                            .pStages = stages.data(),
                                            .pVertexInputState = &vertexInput,
                                            .pInputAssemblyState = &inputAssembly,
                                            .pViewportState = &viewport,
                                            .pRasterizationState = &rasterization,
                                            .pMultisampleState = &multisample,
                                            .pDepthStencilState = &depth,
                                            .pColorBlendState = &blend,
                                            .pDynamicState = &dynamic,
                                            .layout = *layout_};
  return vk::raii::Pipeline(device_.device, cache_.cache(), info);
}

}  // namespace backends::vulkan
