#include "lighting/selection_json.h"

namespace lighting {

nlohmann::ordered_json selectionToJson(const Frame& frame) {
  const Scene& scene = frame.scene();
  using Json = nlohmann::ordered_json;
  Json visible = Json::array();
  // "weight" only when the scene fades (docs/model.md); otherwise SPEC 5.4 exactly.
  const bool fading = scene.pipeline.fadeLastLights > 0;
  for (const VisibleLight& v : frame.selection.visible) {
    Json entry{{"light", v.light}, {"name", scene.lights[v.light].name}, {"packed", v.packed}};
    if (fading) entry["weight"] = v.weight;
    visible.push_back(std::move(entry));
  }

  Json objects = Json::array();
  for (std::size_t i = 0; i < frame.objectLists.size(); ++i) {
    const ObjectLightList& list = frame.objectLists[i];
    objects.push_back(Json{{"name", scene.objects[i].name}, {"count", list.count}, {"indices", list.indices}});
  }

  Json shadowMask = Json::array();
  for (const ShadowMaskEntry& e : frame.prepared->shadowMask.entries)
    shadowMask.push_back(Json{{"light", e.light}, {"name", scene.lights[e.light].name},
                              {"channel", e.channel}, {"demoted", e.demoted}});

  return Json{{"visible", visible}, {"objects", objects}, {"shadow_mask", shadowMask}};
}

}  // namespace lighting
