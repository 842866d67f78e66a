#include "backends/vulkan/forward_pipeline.h"

#include "backends/vulkan/baked_textures.h"
#include "backends/vulkan/cluster_lists.h"
#include "backends/vulkan/light_texture_set.h"
#include "backends/vulkan/scene_uniforms.h"
#include "shaders/embedded_spirv.h"

#include <array>

namespace backends::vulkan {

ForwardPipelines::ForwardPipelines(const VulkanDevice& device, const PipelineCacheFile& cache)
    : builder_(device, cache),
      stages_(device.device, shaders::Stage::ForwardVertex, shaders::Stage::ForwardFragment) {
  const std::array<vk::DescriptorSetLayoutBinding, 2> bindings = SceneUniforms::layoutBindings();
  setLayout_ = vk::raii::DescriptorSetLayout(
      device.device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = bindings.size(), .pBindings = bindings.data()});
  // Set 1 is in every pipeline's layout: the fragment stage's SPIR-V declares
  // the map samplers whatever the LIGHTMAP and SHADOW_MASK constants say.
  mapsSetLayout_ = createBakedMapsSetLayout(device.device);
  // Set 2 is the pass's own input, as in the deferred passes (their G-buffer):
  // here the clustered mode's lists, one texel when the frame has none.
  clusterListsSetLayout_ = ClusterLists::createSetLayout(device.device);
  // Set 3 likewise (the cookies and shadow maps), one set number with the deferred passes.
  lightTextureSetLayout_ = createLightTextureSetLayout(device.device);
  const std::array<vk::DescriptorSetLayout, 4> setLayouts{*setLayout_, *mapsSetLayout_, *clusterListsSetLayout_,
                                                          *lightTextureSetLayout_};
  layout_ = vk::raii::PipelineLayout(
      device.device, vk::PipelineLayoutCreateInfo{.setLayoutCount = setLayouts.size(), .pSetLayouts = setLayouts.data()});
}

const vk::raii::Pipeline& ForwardPipelines::pipeline(const shaders::ConstantValues& constants) {
  return builder_.findOrCreate(pipelines_, constants,
                               [&] { return builder_.buildSceneObjects(layout_, stages_, constants, {kColorFormat}); });
}

}  // namespace backends::vulkan
