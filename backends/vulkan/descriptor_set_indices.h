// The descriptor set of each group of the shader interface, taken from its
// table (shaders/shader_interface.def), and the order in which the pipeline
// layouts list their set layouts (forward_pipeline.cpp, deferred_pipelines.cpp,
// shadow_maps.cpp): every bind names its set here, never by number.
#pragma once

#include "shaders/shader_interface.h"  // generated from shaders/shader_interface.def

#include <cstdint>

namespace backends::vulkan {

// The frame's and the object's blocks (and the deferred passes' blocks).
constexpr std::uint32_t kSceneSetIndex = shaders::binding::kFrameBlock.set;
// The depth-only shadow pass's own block, in its own pipeline layout.
constexpr std::uint32_t kShadowPassSetIndex = shaders::binding::kShadowPassBlock.set;
// An object's baked maps: lightmap and shadow mask.
constexpr std::uint32_t kObjectMapsSetIndex = shaders::binding::kLightmapTexture.set;
// The deferred passes' G-buffer and light buffer, and the forward
// pipeline's cluster lists: set 2 of the two different pipeline layouts.
constexpr std::uint32_t kGbufferSetIndex = shaders::binding::kGbufferAlbedo.set;
constexpr std::uint32_t kClusterListsSetIndex = shaders::binding::kClusterLists.set;
// The cookies' and shadow maps' blocks and textures (light_texture_set.h).
constexpr std::uint32_t kLightTextureSetIndex = shaders::binding::kCookieBlock.set;

// The pipeline layouts list their set layouts by position, in this order.
static_assert(kSceneSetIndex == 0 && kShadowPassSetIndex == 0 && kObjectMapsSetIndex == 1 &&
                  kGbufferSetIndex == 2 && kClusterListsSetIndex == 2 && kLightTextureSetIndex == 3,
              "the pipeline layouts' set-layout arrays follow this order: change them with the table");
static_assert(shaders::binding::kObjectBlock.set == kSceneSetIndex &&
                  shaders::binding::kDeferredLightBlock.set == kSceneSetIndex &&
                  shaders::binding::kDeferredFrameBlock.set == kSceneSetIndex &&
                  shaders::binding::kShadowMaskTexture.set == kObjectMapsSetIndex &&
                  shaders::binding::kLightBuffer.set == kGbufferSetIndex &&
                  shaders::binding::kShadowBlock.set == kLightTextureSetIndex,
              "each group of the table shares its set");

}  // namespace backends::vulkan
