#include "backends/packed_geometry.h"

namespace backends {

PackedGeometry packGeometry(const lighting::PreparedScene& prepared) {
  PackedGeometry packed;
  for (const lighting::ObjectGeometry& object : prepared.objects) {
    const auto vertices = lighting::packVertices(object.mesh);
    const auto indices = lighting::packIndices(object.mesh);
    packed.objects.push_back({std::uint32_t(packed.indices.size()), std::uint32_t(indices.size()),
                              std::int32_t(packed.vertices.size())});
    packed.vertices.insert(packed.vertices.end(), vertices.begin(), vertices.end());
    packed.indices.insert(packed.indices.end(), indices.begin(), indices.end());
  }
  return packed;
}

}  // namespace backends
