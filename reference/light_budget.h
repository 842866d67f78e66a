// Where a frame's light budgets bite (SPEC 5.5), on the reference's visible
// surface at each pixel centre: how many lights reach the point, how many of
// them the model evaluates there, and the light lost, luminance(ideal -
// model). Which lights count is the CPU model's decision (lighting/frame.h);
// this only asks it, pixel by pixel, and says why a reaching light is not kept.
#pragma once

#include "imaging/image.h"
#include "lighting/frame.h"
#include "reference/reference_renderer.h"

#include <cstdint>
#include <vector>

namespace reference {

struct LightBudgetOfLight {
  int light = 0;                    // index in the scene's lights
  std::int64_t reachPixels = 0;     // pixels it reaches
  std::int64_t keptPixels = 0;      // of those, pixels where it is evaluated (per pixel or per vertex)
  std::int64_t vertexPixels = 0;    // of the kept, where it is a vertex light (legacy list positions 4-7)
  std::int64_t frameCutPixels = 0;  // not kept: cut by SPEC 5.1
  std::int64_t objectCutPixels = 0; // not kept: not in the object's list
};

struct LightBudget {
  int width = 0, height = 0;
  // Per pixel, row 0 at the top; 0 on the background.
  std::vector<int> reach;  // lights whose ideal contribution is non-zero there
  std::vector<int> kept;   // of those, the lights the model evaluates there
  imaging::Image lossRgb;  // RGB: ideal - model (the reference's values)
  std::vector<double> loss;          // luminance(ideal - model)
  std::vector<double> lossRelative;  // loss / luminance(ideal); 0 where the ideal is 0
  std::vector<LightBudgetOfLight> lights;  // every light that reaches some pixel, by scene index
  std::int64_t pixelsCut = 0;  // pixels with kept < reach
  double largestLoss = 0, summedLoss = 0, largestRelativeLoss = 0;
};

// A light reaches a point with normal N when its ideal contribution there is
// non-zero (SPEC 5.5): not baked, a non-zero colour, N.L > 0, and for point
// and spot lights inside the range and the cone.
bool lightReaches(const lighting::Light& light, lighting::Profile profile, const lighting::Vec3& point,
                  const lighting::Vec3& normal);

// The frame's budgets. Renders the reference twice (the model and --ideal,
// values only) for the loss.
LightBudget computeLightBudget(const ReferenceRenderer& renderer, const lighting::Frame& frame, int threads = 0);

}  // namespace reference
