// The meshes of one prepared scene in one vertex and one index buffer, with
// where each object's triangles start. Uploaded once per scene: every frame of
// an animated scene draws the same geometry.
#pragma once

#include "backends/packed_geometry.h"
#include "backends/vulkan/gpu_memory.h"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace backends::vulkan {

// How forward.vert reads SceneGeometry::vertices (lighting::GpuVertex:
// position at location 0, normal at 1), for every pipeline that draws the
// scene's meshes (forward, and the deferred G-buffer pass).
struct SceneVertexInput {
  vk::VertexInputBindingDescription binding{.binding = 0, .stride = sizeof(lighting::GpuVertex),
                                            .inputRate = vk::VertexInputRate::eVertex};
  std::array<vk::VertexInputAttributeDescription, 2> attributes{{
      {.location = 0, .binding = 0, .format = vk::Format::eR32G32B32Sfloat, .offset = offsetof(lighting::GpuVertex, position)},
      {.location = 1, .binding = 0, .format = vk::Format::eR32G32B32Sfloat, .offset = offsetof(lighting::GpuVertex, normal)},
  }};
  // Points into this object: keep it alive while the create info is used.
  vk::PipelineVertexInputStateCreateInfo state() const {
    return {.vertexBindingDescriptionCount = 1,
            .pVertexBindingDescriptions = &binding,
            .vertexAttributeDescriptionCount = std::uint32_t(attributes.size()),
            .pVertexAttributeDescriptions = attributes.data()};
  }
};

struct SceneGeometry {
  SceneGeometry(const VulkanDevice& device, std::shared_ptr<const lighting::PreparedScene> prepared,
                const PackedGeometry& packed);

  std::shared_ptr<const lighting::PreparedScene> prepared;  // held, so the pointer identifies the scene
  HostBuffer vertices;
  HostBuffer indices;
  std::vector<ObjectRange> objects;
};

}  // namespace backends::vulkan
