// The meshes of one prepared scene in one vertex and one index buffer, with
// where each object's triangles start. Uploaded once per scene: every frame of
// an animated scene draws the same geometry.
#pragma once

#include "backends/packed_geometry.h"
#include "backends/vulkan/gpu_memory.h"

#include <memory>
#include <vector>

namespace backends::vulkan {

struct SceneGeometry {
  SceneGeometry(const VulkanDevice& device, std::shared_ptr<const lighting::PreparedScene> prepared,
                const PackedGeometry& packed);

  std::shared_ptr<const lighting::PreparedScene> prepared;  // held, so the pointer identifies the scene
  HostBuffer vertices;
  HostBuffer indices;
  std::vector<ObjectRange> objects;
};

}  // namespace backends::vulkan
