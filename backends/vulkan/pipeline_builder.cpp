#include "backends/vulkan/pipeline_builder.h"

#include "backends/vulkan/forward_pipeline.h"
#include "backends/vulkan/raster_translation.h"
#include "backends/vulkan/scene_geometry.h"
#include "shaders/spirv_constant_folding.h"

#include <array>
#include <vector>

namespace backends::vulkan {
namespace {

// Every specialization constant (shaders/shader_interface.def) at its id; a
// stage ignores the ids it does not declare.
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

vk::raii::ShaderModule shaderModule(const vk::raii::Device& device, std::span<const std::uint32_t> spirv) {
  return vk::raii::ShaderModule(device,
                                vk::ShaderModuleCreateInfo{.codeSize = spirv.size_bytes(), .pCode = spirv.data()});
}

// `stage`'s build for `constants` with their admissible variant and mutant,
// lightcts's own deliberate implementations, folded in.
vk::raii::ShaderModule chosenImplementationModule(const vk::raii::Device& device, shaders::Stage stage,
                                                  const shaders::ConstantValues& constants) {
  const shaders::ShaderBuild build = shaders::shaderBuildOf(constants);
  std::vector<std::uint32_t> folded = shaders::withConstantComparisonsFolded(
      shaders::spirv(stage, build), shaders::kAdmissible, constants[shaders::kAdmissible]);
  folded = shaders::withConstantComparisonsFolded(folded, shaders::kMutant, constants[shaders::kMutant]);
  return shaderModule(device, folded);
}

}  // namespace

ShaderStages::ShaderStages(const vk::raii::Device& device, shaders::Stage vertexStage, shaders::Stage fragmentStage)
    : vertexStage(vertexStage),
      fragmentStage(fragmentStage),
      vertex(shaderModule(device, shaders::spirv(vertexStage, shaders::ShaderBuild::Model))),
      fragment(shaderModule(device, shaders::spirv(fragmentStage, shaders::ShaderBuild::Model))) {}

std::pair<vk::ShaderModule, vk::ShaderModule> ShaderStages::modulesFor(const vk::raii::Device& device,
                                                                       const shaders::ConstantValues& constants) const {
  const Choice choice{constants[shaders::kAdmissible], constants[shaders::kMutant]};
  if (choice == Choice{0, 0}) return {*vertex, *fragment};
  auto found = chosen_.find(choice);
  if (found == chosen_.end())
    found = chosen_
                .emplace(choice, std::pair{chosenImplementationModule(device, vertexStage, constants),
                                           chosenImplementationModule(device, fragmentStage, constants)})
                .first;
  return {*found->second.first, *found->second.second};
}

vk::raii::Pipeline PipelineBuilder::build(const vk::raii::PipelineLayout& layout, const ShaderStages& shaderStages,
                                          const shaders::ConstantValues& constants,
                                          const PassPipelineState& pass) const {
  const Specialization specialization(constants);
  const auto [vertexModule, fragmentModule] = shaderStages.modulesFor(device_.device, constants);
  const std::array<vk::PipelineShaderStageCreateInfo, 2> stages{{
      {.stage = vk::ShaderStageFlagBits::eVertex,
       .module = vertexModule,
       .pName = "main",
       .pSpecializationInfo = &specialization.info},
      {.stage = vk::ShaderStageFlagBits::eFragment,
       .module = fragmentModule,
       .pName = "main",
       .pSpecializationInfo = &specialization.info},
  }};
  const vk::PipelineInputAssemblyStateCreateInfo inputAssembly{.topology = vk::PrimitiveTopology::eTriangleList};
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  const vk::PipelineRasterizationStateCreateInfo rasterization = rasterizationInfo(pass.raster);
  // SPEC 1: one sample, at the pixel centre.
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  const vk::PipelineDepthStencilStateCreateInfo depth =
      depthStencilInfo(pass.raster, pass.depthFormat != vk::Format::eUndefined);
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
                                            .pRasterizationState = &rasterization,
                                            .pMultisampleState = &multisample,
                                            .pDepthStencilState = &depth,
                                            .pColorBlendState = &blend,
                                            .pDynamicState = &dynamic,
                                            .layout = *layout};
  return vk::raii::Pipeline(device_.device, cache_.cache(), info);
}

vk::raii::Pipeline PipelineBuilder::buildSceneObjects(const vk::raii::PipelineLayout& layout,
                                                      const ShaderStages& stages,
                                                      const shaders::ConstantValues& constants,
                                                      const std::vector<vk::Format>& colorFormats) const {
  const SceneVertexInput sceneVertices;
  const vk::PipelineVertexInputStateCreateInfo vertexInput = sceneVertices.state();
  const PassPipelineState pass{
      .vertexInput = &vertexInput,
      .raster = lighting::kOpaqueSurfaceState,
      .blend = std::vector<vk::PipelineColorBlendAttachmentState>(colorFormats.size(), unblendedAttachment()),
      .colorFormats = colorFormats,
      .depthFormat = kDepthFormat,
  };
  return build(layout, stages, constants, pass);
}

}  // namespace backends::vulkan
