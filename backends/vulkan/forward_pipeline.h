// The forward pipeline: two descriptor set layouts (set 0, binding 0: the
// frame block, binding 1: the object block with a dynamic offset per draw;
// set 1: the object's baked maps, baked_textures.h), the embedded
// SPIR-V stages, and one pipeline per set of specialization constants, built
// on first use through the on-disk pipeline cache.
#pragma once

#include "backends/vulkan/pipeline_cache_file.h"
#include "backends/vulkan/vulkan_device.h"
#include "shaders/shader_constants.h"

#include <map>

namespace backends::vulkan {

constexpr vk::Format kColorFormat = vk::Format::eR32G32B32A32Sfloat;
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

class ForwardPipelines {
 public:
  ForwardPipelines(const VulkanDevice& device, const PipelineCacheFile& cache);

  const vk::raii::DescriptorSetLayout& setLayout() const { return setLayout_; }
  const vk::raii::DescriptorSetLayout& mapsSetLayout() const { return mapsSetLayout_; }
  const vk::raii::PipelineLayout& layout() const { return layout_; }
  bool contains(const shaders::ConstantValues& constants) const { return pipelines_.contains(constants); }
  // The pipeline specialised with `constants`, created (and the cache file
  // saved) the first time it is asked for.
  const vk::raii::Pipeline& pipeline(const shaders::ConstantValues& constants);

 private:
  vk::raii::Pipeline create(const shaders::ConstantValues& constants) const;

  const VulkanDevice& device_;
  const PipelineCacheFile& cache_;
  vk::raii::DescriptorSetLayout setLayout_{nullptr};
  vk::raii::DescriptorSetLayout mapsSetLayout_{nullptr};
  vk::raii::PipelineLayout layout_{nullptr};
  vk::raii::ShaderModule vertex_{nullptr};
  vk::raii::ShaderModule fragment_{nullptr};
  std::map<shaders::ConstantValues, vk::raii::Pipeline> pipelines_;
};

}  // namespace backends::vulkan
