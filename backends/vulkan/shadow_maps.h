// The real-time shadow maps of SPEC 3.9 on the device: their bindings of the
// light texture set (light_texture_set.h, shaders/shadows.glsl: the frame's
// lighting::GpuShadowBlock, the 2D slots and the cube slots) and the
// depth-only passes that fill them.
//
// Each slot has a D32_SFLOAT depth image of its light's resolution (a cube
// for a point light), kept while the resolution stays. Every draw records
// one pass per lighting::ShadowPassView (every object, shadow_caster.vert,
// lighting::kShadowCasterState) before the lighting passes, then hands the
// maps to the fragment stage; an unused slot is a 1 x 1 map cleared to 1
// once, so the set is always valid, in scenes without shadows too, and such
// scenes pay for no pass. The compare
// samplers are LESS_OR_EQUAL (LESS for the shadow-compare-less mutant),
// nearest for `hard`, linear otherwise, clamped to the edge.
#pragma once

#include "backends/vulkan/gpu_memory.h"
#include "backends/vulkan/light_texture_set.h"
#include "backends/vulkan/pipeline_builder.h"
#include "backends/vulkan/scene_geometry.h"
#include "backends/vulkan/scene_uniforms.h"
#include "imaging/image.h"
#include "lighting/frame.h"
#include "lighting/shadow_packing.h"
#include "shaders/shader_variant.h"

#include <array>
#include <optional>
#include <vector>

namespace backends::vulkan {

class ShadowMaps {
 public:
  // Writes its bindings of `set` (stand-ins until the first update).
  ShadowMaps(const VulkanDevice& device, const PipelineCacheFile& cache, vk::DescriptorSet set,
             shaders::Mutant mutant);
  ShadowMaps(const ShadowMaps&) = delete;  // the descriptor infos point at members

  // Makes the depth images `frame`'s slots need (NotSupportedError where the
  // device cannot filter or hold them), writes the frame's blocks and points
  // the set at this frame's maps. Call only while no submitted command
  // buffer uses the set.
  void update(const lighting::Frame& frame);
  // Records every view's depth pass of the frame last updated, and the
  // barriers that hand those slots to the lighting passes' fragment stage;
  // a slot made since the last draw is cleared to 1 once. A frame without
  // shadow maps records nothing once every slot is ready.
  void record(const vk::raii::CommandBuffer& commands, const SceneGeometry& geometry);
  // Records copies of every view of the last recorded maps into a staging
  // buffer (readback evidence), leaving them sampled again.
  void recordReadback(const vk::raii::CommandBuffer& commands);
  // After the recorded readback completed: one depth image per view.
  std::vector<imaging::Image> readbackImages() const;
  bool any() const { return !views_.empty(); }

 private:
  struct SlotImage {
    std::optional<DeviceImage> image;
    std::vector<vk::raii::ImageView> faces;  // per layer: the attachment view of one face
    int resolution = 0;
    bool cube = false;
    bool ready = false;  // cleared or drawn, and left in the sampled layout
  };
  void ensureSlot(SlotImage& slot, int resolution, bool cube);
  void writeSet(const lighting::Frame* frame);

  const VulkanDevice& device_;
  vk::raii::Sampler nearest_{nullptr}, linear_{nullptr};
  std::array<SlotImage, lighting::kGpuShadowSlots> slots_;
  HostBuffer block_;
  vk::DescriptorSet set_;
  // The depth passes: their own set 0 (ShadowPassBlock, the view's
  // transform, and ObjectBlock, both dynamic) and pipeline.
  vk::raii::DescriptorSetLayout passSetLayout_{nullptr};
  vk::raii::PipelineLayout passLayout_{nullptr};
  ShaderStages stages_;
  vk::raii::Pipeline pipeline_{nullptr};
  vk::DeviceSize viewStride_ = 0;
  HostBuffer viewBlocks_;
  std::optional<SceneUniforms> objects_;
  DescriptorSets passSets_;
  std::vector<lighting::ShadowPassView> views_;
  std::optional<HostBuffer> staging_;  // readback evidence
};

}  // namespace backends::vulkan
