// The light cookies of SPEC 3.10 on the device: their bindings of the light
// texture set (light_texture_set.h, shaders/cookies.glsl): the frame's
// lighting::GpuCookieBlock, the 2D slots and the cube slots, read by the
// vertex stage (legacy vertex lights) and the fragment stage.
//
// Every cookie of a prepared scene is uploaded once (R32F, its value,
// backends/cookie_texels.h); each frame writes its block and points the slots
// at the images of the lights lighting::assignCookieSlots gave them, which
// can change from frame to frame (popping). Unused slots hold 1x1 stand-ins,
// so the set is always valid, in scenes without cookies too.
#pragma once

#include "backends/vulkan/gpu_memory.h"
#include "backends/vulkan/light_texture_set.h"
#include "lighting/frame.h"

#include <memory>
#include <optional>
#include <vector>

namespace backends::vulkan {

class CookieTextures {
 public:
  // Writes its bindings of `set` (stand-ins until the first update).
  CookieTextures(const VulkanDevice& device, vk::DescriptorSet set);
  CookieTextures(const CookieTextures&) = delete;  // the descriptor infos point at members

  // Uploads `frame`'s scene's cookies when the prepared scene is new (throws
  // NotSupportedError when the device cannot filter them or hold their
  // size), then writes the frame's block and slots into the set. Call only
  // while no submitted command buffer uses the set.
  void update(const lighting::Frame& frame);
  // Wall time of the last scene's upload (0 for a scene without cookies).
  double uploadMilliseconds() const { return uploadMilliseconds_; }

 private:
  void upload(const std::shared_ptr<const lighting::PreparedScene>& prepared);
  void writeSet(const lighting::Frame* frame);

  const VulkanDevice& device_;
  vk::raii::Sampler repeat_{nullptr};   // directional: tiled
  vk::raii::Sampler clamp_{nullptr};    // spot, and the cubes (seamless whatever the address mode)
  vk::raii::Sampler nearest_{nullptr};  // the stand-ins: no linear-filter format feature needed
  DeviceImage noTexture_;
  DeviceImage noCube_;
  HostBuffer block_;
  std::shared_ptr<const lighting::PreparedScene> scene_;
  std::vector<std::optional<DeviceImage>> images_;  // per scene light: its cookie, if it has one
  vk::DescriptorSet set_;
  double uploadMilliseconds_ = 0;
};

}  // namespace backends::vulkan
