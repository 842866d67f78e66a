#include "reference/light_budget.h"

#include "lighting/light_math.h"
#include "reference/parallel_rows.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace reference {

using lighting::Frame;
using lighting::Light;
using lighting::LightType;
using lighting::Vec3;


bool lightReaches(const Light& light, lighting::Profile profile, const Vec3& point, const Vec3& normal) {
  const Vec3 colour = light.finalColor();
  if (!(colour.r > 0 || colour.g > 0 || colour.b > 0)) return false;
  if (light.type == LightType::Directional) return glm::dot(normal, -light.direction) > 0;
  // SPEC 3.2: the clamped distance, L, the range window and the spot term;
  // the light adds nothing exactly where one of them is 0.
  const Vec3 ray = light.position - point;
  const double distanceSquared = std::max(glm::dot(ray, ray), lighting::kMinDistanceSquared);
  const Vec3 L = ray / std::sqrt(distanceSquared);
  if (!(glm::dot(normal, L) > 0)) return false;
  if (!(lighting::rangeAttenuation(distanceSquared, lighting::inverseRangeSquared(light.range)) > 0)) return false;
  if (light.type == LightType::Point) return true;
  return lighting::spotAttenuation(glm::dot(-light.direction, L), lighting::lightSpotFactors(light, profile)) > 0;
}

namespace {

// Per object: which of the frame's candidate lights it evaluates, and how.
enum class Kept : std::uint8_t { No, PerPixel, PerVertex };

struct ObjectBudget {
  std::map<int, Kept> kept;  // scene light -> how the object evaluates it
};

// How each object evaluates each candidate light (Frame::lightsForObject),
// and for a light it does not evaluate, whether the frame cut it already.
std::vector<ObjectBudget> objectBudgets(const Frame& frame) {
  std::vector<ObjectBudget> objects(frame.scene().objects.size());
  for (std::size_t o = 0; o < objects.size(); ++o) {
    const lighting::ObjectLights lights = frame.lightsForObject(int(o));
    for (int l : lights.perPixel) objects[o].kept[l] = Kept::PerPixel;
    for (int l : lights.perVertex) objects[o].kept[l] = Kept::PerVertex;
  }
  return objects;
}

bool keptByFrame(const Frame& frame, int light) {
  const lighting::PackedLights& packed = frame.selection.packed;
  return std::find(packed.directional.begin(), packed.directional.end(), light) != packed.directional.end() ||
         std::find(packed.other.begin(), packed.other.end(), light) != packed.other.end();
}

}  // namespace

LightBudget computeLightBudget(const ReferenceRenderer& renderer, const Frame& frame, int threads) {
  const lighting::Scene& scene = frame.scene();
  LightBudget budget;
  budget.width = frame.view.width;
  budget.height = frame.view.height;
  const std::size_t pixels = std::size_t(budget.width) * budget.height;
  budget.reach.assign(pixels, 0);
  budget.kept.assign(pixels, 0);
  budget.loss.assign(pixels, 0.0);
  budget.lossRelative.assign(pixels, 0.0);

  // The candidates: every light that is not baked (SPEC 6's --ideal set).
  const std::vector<int> candidates = frame.idealLightsForObject().perPixel;
  const std::vector<ObjectBudget> objects = objectBudgets(frame);
  std::vector<bool> frameKept(scene.lights.size(), false);
  for (int l : candidates) frameKept[std::size_t(l)] = keptByFrame(frame, l);

  // Per row, per light counts, summed after: rows run on several threads.
  const std::size_t lightCount = scene.lights.size();
  std::vector<std::vector<LightBudgetOfLight>> rowCounts(std::size_t(budget.height),
                                                         std::vector<LightBudgetOfLight>(lightCount));
  forEachRow(budget.height, threads, [&](int y) {
    std::vector<LightBudgetOfLight>& counts = rowCounts[std::size_t(y)];
    for (int x = 0; x < budget.width; ++x) {
      const auto surface = renderer.visibleSurface(frame, x, y);
      if (!surface) continue;
      const std::size_t k = std::size_t(y) * budget.width + x;
      const ObjectBudget& object = objects[std::size_t(surface->object)];
      for (int l : candidates) {
        if (!lightReaches(scene.lights[std::size_t(l)], scene.pipeline.profile, surface->point, surface->normal))
          continue;
        LightBudgetOfLight& c = counts[std::size_t(l)];
        ++budget.reach[k];
        ++c.reachPixels;
        const auto how = object.kept.find(l);
        if (how != object.kept.end()) {
          ++budget.kept[k];
          ++c.keptPixels;
          if (how->second == Kept::PerVertex) ++c.vertexPixels;
        } else if (!frameKept[std::size_t(l)]) {
          ++c.frameCutPixels;
        } else {
          ++c.objectCutPixels;
        }
      }
    }
  });
  for (std::size_t l = 0; l < lightCount; ++l) {
    LightBudgetOfLight total;
    total.light = int(l);
    for (const auto& row : rowCounts) {
      total.reachPixels += row[l].reachPixels;
      total.keptPixels += row[l].keptPixels;
      total.vertexPixels += row[l].vertexPixels;
      total.frameCutPixels += row[l].frameCutPixels;
      total.objectCutPixels += row[l].objectCutPixels;
    }
    if (total.reachPixels > 0) budget.lights.push_back(total);
  }

  // The loss: the reference's own values, the model against --ideal.
  ReferenceOptions options;
  options.valueOnly = true;
  options.threads = threads;
  options.bakedLightsRealtime = scene.expect.against == lighting::CompareAgainst::Realtime;
  const ReferenceImages model = renderer.render(frame, options);
  options.ideal = true;
  const ReferenceImages ideal = renderer.render(frame, options);
  budget.lossRgb = imaging::Image(budget.width, budget.height, 3);
  for (int y = 0; y < budget.height; ++y) {
    for (int x = 0; x < budget.width; ++x) {
      const std::size_t k = std::size_t(y) * budget.width + x;
      Vec3 ideal3, model3;
      for (int c = 0; c < 3; ++c) {
        ideal3[c] = ideal.value.at(x, y, c);
        model3[c] = model.value.at(x, y, c);
        budget.lossRgb.at(x, y, c) = float(ideal3[c] - model3[c]);
      }
      budget.loss[k] = lighting::luminance(ideal3 - model3);
      const double idealLuminance = lighting::luminance(ideal3);
      budget.lossRelative[k] = idealLuminance > 0 ? budget.loss[k] / idealLuminance : 0.0;
      if (budget.kept[k] < budget.reach[k]) ++budget.pixelsCut;
      budget.largestLoss = std::max(budget.largestLoss, budget.loss[k]);
      budget.largestRelativeLoss = std::max(budget.largestRelativeLoss, budget.lossRelative[k]);
      budget.summedLoss += budget.loss[k];
    }
  }
  return budget;
}

}  // namespace reference
