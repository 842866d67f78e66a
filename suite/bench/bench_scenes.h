// The synthetic scenes of the frame benchmarks (docs/bench-format.md): a
// field of floor tiles seen from straight above with point lights over it,
// sized so every pixel is covered and every light is in view. The 1280x720
// 64-light field (`lights64-1280x720`) and the cost curves (`curve-lights`,
// `curve-resolution`, `curve-objects`) are all this one generator.
#pragma once

#include "lighting/scene.h"

#include <string>
#include <string_view>

namespace bench {

// The `mode` part of a benchmark name: which pipeline and shader variant.
enum class FrameMode {
  AllLights,   // srp forward, every kept light per pixel
  PerObject,   // srp forward, per-object lists (at most 8 lights per object)
  Legacy4x4,   // legacy profile: lists always on, 4 pixel + 4 vertex lights, 16 kept lights
};

std::string_view modeName(FrameMode mode);

struct FieldSpec {
  int width = 1280, height = 720;
  // The floor: tileColumns x tileRows tiles covering exactly the view
  // (7.2 world units tall, 7.2 * width / height wide).
  int tileColumns = 8, tileRows = 8;
  // A 0.5 box on every other interior tile corner (16 on the 8x8 field).
  bool boxes = true;
  // Point lights 0.4 above the centres of a lightColumns x lightRows grid
  // over the field; the range scales with the cell (0.85 on 1.6 x 0.9 cells).
  int lightColumns = 8, lightRows = 8;
  FrameMode mode = FrameMode::AllLights;
};

// The scene of `spec` (the mode's profile and lists set; the shader variant
// is the backend's business).
lighting::Scene fieldScene(const FieldSpec& spec, const std::string& name);

// A light grid of `count` lights (1, 2, 4, ... powers of two): columns >= rows.
void lightGridFor(int count, int& columns, int& rows);

}  // namespace bench
