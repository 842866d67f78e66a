// The baked maps of SPEC 3.6 on the device: descriptor set 1 of the forward
// pipeline (lightmapTexture and shadowMaskTexture at their bindings of
// shaders/shader_interface.def, both combined image samplers read by the
// fragment stage).
//
// The forward shader uses set 1 statically, so every draw binds one: objects
// with maps get a set of their own pointing at their two RGBA32F images
// (sampled bilinearly, clamp to edge); every other object shares one set of
// 1x1 stand-ins, lightmap (0, 0, 0, 1) and mask (1, 1, 1, 1), which the
// shader does not read for them (objectData.lightList.y/.z are 0) but which
// keep the set valid.
#pragma once

#include "backends/vulkan/descriptor_sets.h"
#include "backends/vulkan/gpu_memory.h"
#include "lighting/frame.h"

#include <memory>
#include <vector>

namespace backends::vulkan {

// The layout of set 1 (both bindings, fragment stage).
vk::raii::DescriptorSetLayout createBakedMapsSetLayout(const vk::raii::Device& device);

// What does not depend on a scene: the samplers, the 1x1 stand-ins and the set
// that points at them. Made once per backend.
class BakedMapDefaults {
 public:
  BakedMapDefaults(const VulkanDevice& device, const vk::raii::DescriptorSetLayout& layout);

  // LINEAR min/mag, NEAREST between mips (there is one), clamp to edge: SPEC
  // 3.5 and 3.6's bilinear, clamp-to-edge sample.
  const vk::raii::Sampler& bilinear() const { return bilinear_; }
  // For the 1x1 stand-ins: one texel reads the same under either filter, and
  // NEAREST needs no SAMPLED_IMAGE_FILTER_LINEAR, so a device that cannot
  // filter RGBA32F still draws every scene without maps.
  const vk::raii::Sampler& nearest() const { return nearest_; }
  const DeviceImage& noLightmap() const { return noLightmap_; }
  const DeviceImage& noShadowMask() const { return noShadowMask_; }
  vk::DescriptorSet noMapsSet() const { return *sets_.sets.front(); }

 private:
  vk::raii::Sampler bilinear_{nullptr};
  vk::raii::Sampler nearest_{nullptr};
  DeviceImage noLightmap_;
  DeviceImage noShadowMask_;
  DescriptorSets sets_;  // the one set pointing at the 1x1 defaults
};

// The maps of one prepared scene's bake, uploaded once (texel (i, j) is row j
// of its image, as lighting::TexelMap lays it out) and one set per object.
// Holds the prepared scene and its bake, so the pointers identify them: a
// new prepared scene or a new bake (a CPU mutant swaps it) needs a new one.
class SceneBakedTextures {
 public:
  // Throws std::logic_error (from PreparedScene::bakeOf) for a scene that
  // needs a bake it does not have, and NotSupportedError when the device
  // cannot filter the maps. A scene without maps makes no Vulkan call.
  SceneBakedTextures(const VulkanDevice& device, const BakedMapDefaults& defaults,
                     const vk::raii::DescriptorSetLayout& layout,
                     std::shared_ptr<const lighting::PreparedScene> prepared);

  bool isFor(const lighting::PreparedScene& scene) const {
    return &scene == prepared_.get() && scene.baked.get() == baked_.get();
  }
  // Set 1 for object `object`.
  vk::DescriptorSet set(std::size_t object) const { return sets_[object]; }
  // Wall time of the upload (0 when the scene has no maps).
  double uploadMilliseconds() const { return uploadMilliseconds_; }

 private:
  std::shared_ptr<const lighting::PreparedScene> prepared_;
  std::shared_ptr<const lighting::BakedLighting> baked_;
  // Declared before the sets, so the sets are freed before what they point at.
  std::vector<DeviceImage> images_;
  DescriptorSets ownSets_;  // one per object with maps
  std::vector<vk::DescriptorSet> sets_;  // per object: its own set or the defaults' one
  double uploadMilliseconds_ = 0;
};

}  // namespace backends::vulkan
