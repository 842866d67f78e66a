// Builds the graphics pipelines of every pass (forward, G-buffer, light,
// composite; a shadow-map pass would be one more buildSceneObjects call with
// no colour format) the same way: two stages specialised with every constant
// of shaders/shader_interface.def, a triangle list, dynamic viewport and
// scissor, one sample, dynamic rendering, through the on-disk pipeline cache.
// What differs between passes is the PassPipelineState; its raster state is
// the model's (lighting/raster_state.h), translated by raster_translation.h.
#pragma once

#include "shaders/embedded_spirv.h"
#include "backends/vulkan/pipeline_cache_file.h"
#include "backends/vulkan/vulkan_device.h"
#include "lighting/raster_state.h"
#include "shaders/shader_constants.h"

#include <cstdint>
#include <map>
#include <utility>
#include <span>
#include <vector>

namespace backends::vulkan {

// A pass's vertex and fragment shader modules, from embedded SPIR-V.
// A vertex and a fragment stage (shaders/embedded_spirv.h): a pipeline takes
// the build its constants ask for (shaders::shaderBuildOf). The model's build
// is made into modules once; the pipelines of an admissible variant or a
// mutant get modules of its build with that choice folded in
// (shaders/spirv_constant_folding.h), made once per variant and mutant.
struct ShaderStages {
  ShaderStages(const vk::raii::Device& device, shaders::Stage vertexStage, shaders::Stage fragmentStage);

  // The vertex and fragment modules a pipeline with `constants` runs: the
  // model's, or those of its admissible variant and mutant, made the first
  // time that pair is asked for.
  std::pair<vk::ShaderModule, vk::ShaderModule> modulesFor(const vk::raii::Device& device,
                                                           const shaders::ConstantValues& constants) const;

  shaders::Stage vertexStage, fragmentStage;
  vk::raii::ShaderModule vertex, fragment;  // the model's build

 private:
  using Choice = std::pair<std::int32_t, std::int32_t>;  // ADMISSIBLE, MUTANT
  mutable std::map<Choice, std::pair<vk::raii::ShaderModule, vk::raii::ShaderModule>> chosen_;
};

struct PassPipelineState {
  const vk::PipelineVertexInputStateCreateInfo* vertexInput = nullptr;
  lighting::RasterState raster;
  std::vector<vk::PipelineColorBlendAttachmentState> blend;  // one per colour attachment
  std::vector<vk::Format> colorFormats;
  vk::Format depthFormat = vk::Format::eUndefined;  // undefined: no depth attachment, no depth test
};

class PipelineBuilder {
 public:
  PipelineBuilder(const VulkanDevice& device, const PipelineCacheFile& cache) : device_(device), cache_(cache) {}

  const VulkanDevice& device() const { return device_; }

  vk::raii::Pipeline build(const vk::raii::PipelineLayout& layout, const ShaderStages& stages,
                           const shaders::ConstantValues& constants, const PassPipelineState& pass) const;
  // A pass that draws the scene's objects (recordSceneObjectsPass): the scene
  // vertex input of forward.vert, lighting::kOpaqueSurfaceState, one
  // unblended attachment per colour format, D32 depth.
  vk::raii::Pipeline buildSceneObjects(const vk::raii::PipelineLayout& layout, const ShaderStages& stages,
                                       const shaders::ConstantValues& constants,
                                       const std::vector<vk::Format>& colorFormats) const;

  // The pipeline under `key` in `map`, created (and the cache file saved)
  // the first time it is asked for.
  template <class Map, class Key, class Create>
  const vk::raii::Pipeline& findOrCreate(Map& map, const Key& key, Create&& create) const {
    auto found = map.find(key);
    if (found != map.end()) return found->second;
    auto [inserted, _] = map.emplace(key, create());
    cache_.save();
    return inserted->second;
  }

 private:
  const VulkanDevice& device_;
  const PipelineCacheFile& cache_;
};

}  // namespace backends::vulkan
