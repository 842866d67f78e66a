#include "backends/vulkan/scene_geometry.h"

namespace backends::vulkan {
namespace {

// Vulkan buffers may not be empty; a scene with no objects still gets one.
vk::DeviceSize atLeastOne(std::size_t bytes) { return bytes == 0 ? 4 : bytes; }

}  // namespace

SceneGeometry::SceneGeometry(const VulkanDevice& device, std::shared_ptr<const lighting::PreparedScene> scene,
                             const PackedGeometry& packed)
    : prepared(std::move(scene)),
      vertices(device, atLeastOne(packed.vertices.size() * sizeof(lighting::GpuVertex)),
               vk::BufferUsageFlagBits::eVertexBuffer),
      indices(device, atLeastOne(packed.indices.size() * sizeof(std::uint32_t)), vk::BufferUsageFlagBits::eIndexBuffer),
      objects(packed.objects) {
  vertices.write(std::span(packed.vertices));
  indices.write(std::span(packed.indices));
}

}  // namespace backends::vulkan
