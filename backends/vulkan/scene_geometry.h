// The meshes of one prepared scene in one vertex and one index buffer, with
// where each object's triangles start. Uploaded once per scene: every frame of
// an animated scene draws the same geometry.
#pragma once

#include "backends/vulkan/gpu_memory.h"
#include "lighting/frame.h"
#include "lighting/gpu_packing.h"

#include <memory>
#include <vector>

namespace backends::vulkan {

struct ObjectRange {
  std::uint32_t firstIndex = 0;
  std::uint32_t indexCount = 0;
  std::int32_t vertexOffset = 0;
};

// Every object's vertices and indices, concatenated on the CPU.
struct PackedGeometry {
  std::vector<lighting::GpuVertex> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<ObjectRange> objects;
};
PackedGeometry packGeometry(const lighting::PreparedScene& prepared);

struct SceneGeometry {
  SceneGeometry(const VulkanDevice& device, std::shared_ptr<const lighting::PreparedScene> prepared,
                const PackedGeometry& packed);

  std::shared_ptr<const lighting::PreparedScene> prepared;  // held, so the pointer identifies the scene
  HostBuffer vertices;
  HostBuffer indices;
  std::vector<ObjectRange> objects;
};

}  // namespace backends::vulkan
