// Every object's vertices and indices concatenated on the CPU, with where each
// object's triangles start: what every backend uploads once per scene.
#pragma once

#include "lighting/frame.h"
#include "lighting/gpu_packing.h"

#include <cstdint>
#include <vector>

namespace backends {

struct ObjectRange {
  std::uint32_t firstIndex = 0;
  std::uint32_t indexCount = 0;
  std::int32_t vertexOffset = 0;
};

struct PackedGeometry {
  std::vector<lighting::GpuVertex> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<ObjectRange> objects;
};

PackedGeometry packGeometry(const lighting::PreparedScene& prepared);

}  // namespace backends
