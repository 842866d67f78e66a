// The scene format's words for the model's enums (SPEC 2), one table each
// where more than the loader names them: the scene loader
// (scene_input/scene_loader.cpp) reads a file with these tables, and whoever
// writes or names a value (a printed scene, a message, a benchmark name) uses
// them too, so both speak the file's words.
#pragma once

#include "lighting/scene.h"

#include <array>
#include <cstddef>
#include <string_view>

namespace lighting {

template <typename T>
struct SceneWord {
  std::string_view name;
  T value;
};

// SPEC 1 `camera.projection`.
inline constexpr std::array<SceneWord<Projection>, 2> kProjectionWords{
    {{"perspective", Projection::Perspective}, {"orthographic", Projection::Orthographic}}};
// SPEC 2 `lights[i].type`.
inline constexpr std::array<SceneWord<LightType>, 3> kLightTypeWords{
    {{"directional", LightType::Directional}, {"point", LightType::Point}, {"spot", LightType::Spot}}};
// SPEC 2 `pipeline.deferred_buffer`.
inline constexpr std::array<SceneWord<DeferredBuffer>, 3> kDeferredBufferWords{
    {{"hdr32", DeferredBuffer::Hdr32}, {"hdr16", DeferredBuffer::Hdr16}, {"ldr8", DeferredBuffer::Ldr8}}};

// The word of `value` in `words`, or "?" for a value the table lacks.
template <typename T, std::size_t N>
constexpr std::string_view wordOf(const std::array<SceneWord<T>, N>& words, T value) {
  for (const SceneWord<T>& word : words)
    if (word.value == value) return word.name;
  return "?";
}

// "hdr32", "hdr16" or "ldr8".
inline std::string_view deferredBufferName(DeferredBuffer buffer) { return wordOf(kDeferredBufferWords, buffer); }

}  // namespace lighting
