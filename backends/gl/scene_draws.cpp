#include "backends/gl/scene_draws.h"

#include "backends/gl/forward_programs.h"
#include "lighting/gpu_packing.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace backends::gl {

void SceneDraws::update(const lighting::Frame& frame) {
  uploadGeometry(frame);
  writeUniforms(frame);
}

void SceneDraws::bindFrameBlock() const {
  gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kFrameBlock.glBinding, frameUniforms_.get(), 0,
                        sizeof(lighting::GpuFrameBlock));
}

void SceneDraws::drawObjects(const BakedTextures& baked) const { draw(&baked); }

void SceneDraws::drawGeometry() const { draw(nullptr); }

void SceneDraws::draw(const BakedTextures* baked) const {
  gl_.glBindVertexArray(vertexArray_.get());
  bindFrameBlock();
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const ObjectRange& range = objects_[o];
    if (range.indexCount == 0) continue;
    gl_.glBindBufferRange(GL_UNIFORM_BUFFER, shaders::binding::kObjectBlock.glBinding, objectUniforms_.get(),
                          GLintptr(o * objectStride_), sizeof(lighting::GpuObjectBlock));
    if (baked) baked->bind(int(o));
    const auto firstIndex = reinterpret_cast<const void*>(std::uintptr_t(range.firstIndex) * sizeof(std::uint32_t));
    gl_.glDrawElementsBaseVertex(GL_TRIANGLES, GLsizei(range.indexCount), GL_UNSIGNED_INT, firstIndex,
                                 range.vertexOffset);
  }
  gl_.glBindVertexArray(0);
}

void SceneDraws::uploadGeometry(const lighting::Frame& frame) {
  if (scene_ == frame.prepared) return;
  const PackedGeometry packed = packGeometry(*frame.prepared);
  vertexArray_ = makeVertexArray(gl_);
  vertices_ = makeBuffer(gl_);
  indices_ = makeBuffer(gl_);
  gl_.glBindVertexArray(vertexArray_.get());
  gl_.glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
  gl_.glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(packed.vertices.size() * sizeof(lighting::GpuVertex)),
                   packed.vertices.data(), GL_STATIC_DRAW);
  gl_.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
  gl_.glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(packed.indices.size() * sizeof(std::uint32_t)),
                   packed.indices.data(), GL_STATIC_DRAW);
  // Locations 0 and 1, as forward.vert declares them.
  gl_.glEnableVertexAttribArray(0);
  gl_.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(lighting::GpuVertex),
                            reinterpret_cast<const void*>(offsetof(lighting::GpuVertex, position)));
  gl_.glEnableVertexAttribArray(1);
  gl_.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(lighting::GpuVertex),
                            reinterpret_cast<const void*>(offsetof(lighting::GpuVertex, normal)));
  gl_.glBindVertexArray(0);
  objects_ = packed.objects;
  scene_ = frame.prepared;
  gl_.check("uploading the scene's geometry");
}

void SceneDraws::writeUniforms(const lighting::Frame& frame) {
  if (!frameUniforms_.get()) {
    frameUniforms_ = makeBuffer(gl_);
    objectUniforms_ = makeBuffer(gl_);
    objectStride_ = uniformBlockStride(gl_, sizeof(lighting::GpuObjectBlock));
  }
  const lighting::GpuFrameBlock block = lighting::packFrameBlock(frame, grid_);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, frameUniforms_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, sizeof(block), &block, GL_DYNAMIC_DRAW);
  std::vector<unsigned char> objects(std::max<std::size_t>(objects_.size(), 1) * objectStride_);
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const lighting::GpuObjectBlock object = lighting::packObjectBlock(frame, int(o));
    std::memcpy(&objects[o * objectStride_], &object, sizeof(object));
  }
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, objectUniforms_.get());
  gl_.glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(objects.size()), objects.data(), GL_DYNAMIC_DRAW);
  gl_.glBindBuffer(GL_UNIFORM_BUFFER, 0);
  gl_.check("writing the uniform buffers");
}

}  // namespace backends::gl
