// The forward pipeline: its descriptor set layouts (set 0: the scene's
// uniforms, scene_uniforms.h; set 1: the object's baked maps,
// baked_textures.h; set 2: the clustered mode's lists, cluster_lists.h, where
// the deferred passes have their G-buffer; set 3:
// the cookies and shadow maps, light_texture_set.h), forward.vert and forward.frag, and one pipeline per set
// of specialization constants, built on first use (pipeline_builder.h).
#pragma once

#include "backends/vulkan/pipeline_builder.h"

#include <map>

namespace backends::vulkan {

constexpr vk::Format kColorFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

class ForwardPipelines {
 public:
  ForwardPipelines(const VulkanDevice& device, const PipelineCacheFile& cache);

  const vk::raii::DescriptorSetLayout& setLayout() const { return setLayout_; }
  const vk::raii::DescriptorSetLayout& mapsSetLayout() const { return mapsSetLayout_; }
  const vk::raii::DescriptorSetLayout& clusterListsSetLayout() const { return clusterListsSetLayout_; }
  const vk::raii::DescriptorSetLayout& lightTextureSetLayout() const { return lightTextureSetLayout_; }
  const vk::raii::PipelineLayout& layout() const { return layout_; }
  bool contains(const shaders::ConstantValues& constants) const { return pipelines_.contains(constants); }
  // The pipeline specialised with `constants`, created (and the cache file
  // saved) the first time it is asked for.
  const vk::raii::Pipeline& pipeline(const shaders::ConstantValues& constants);

 private:
  PipelineBuilder builder_;
  ShaderStages stages_;
  vk::raii::DescriptorSetLayout setLayout_{nullptr};
  vk::raii::DescriptorSetLayout mapsSetLayout_{nullptr};
  vk::raii::DescriptorSetLayout clusterListsSetLayout_{nullptr};
  vk::raii::DescriptorSetLayout lightTextureSetLayout_{nullptr};
  vk::raii::PipelineLayout layout_{nullptr};
  std::map<shaders::ConstantValues, vk::raii::Pipeline> pipelines_;
};

}  // namespace backends::vulkan
