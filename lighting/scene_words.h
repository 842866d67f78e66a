// The scene format's words for the model's enums (SPEC 2), one table each:
// the scene loader (scene_input/scene_loader.cpp) reads a file with them, and
// whoever names a value in a message or a benchmark name uses them too, so
// both speak the file's words.
#pragma once

#include "lighting/scene.h"

#include <array>
#include <string_view>

namespace lighting {

template <typename T>
struct SceneWord {
  std::string_view name;
  T value;
};

// SPEC 2 `pipeline.deferred_buffer`.
inline constexpr std::array<SceneWord<DeferredBuffer>, 3> kDeferredBufferWords{
    {{"hdr32", DeferredBuffer::Hdr32}, {"hdr16", DeferredBuffer::Hdr16}, {"ldr8", DeferredBuffer::Ldr8}}};

// "hdr32", "hdr16" or "ldr8".
inline std::string_view deferredBufferName(DeferredBuffer buffer) {
  for (const SceneWord<DeferredBuffer>& word : kDeferredBufferWords)
    if (word.value == buffer) return word.name;
  return "?";
}

}  // namespace lighting
