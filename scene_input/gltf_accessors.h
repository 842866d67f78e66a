// Reading a glTF accessor's elements out of its buffer, with every range that
// glTF 2.0 requires checked (offset, stride and count inside the buffer view,
// the view inside its buffer, indices below the vertex count, floats finite).
// The JSON has passed checkGltfJson, so types and indices are known to be
// well-formed; what is checked here is what needs the bytes.
#pragma once

#include "lighting/scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace scene_input {

// The bytes of every buffer of the file, by buffer index.
using GltfBuffers = std::vector<std::vector<unsigned char>>;

class GltfAccessors {
 public:
  GltfAccessors(const nlohmann::json& document, const GltfBuffers& buffers, std::string file)
      : document_(document), buffers_(buffers), file_(std::move(file)) {}

  // A VEC3 FLOAT accessor (POSITION, NORMAL), every component finite.
  std::vector<lighting::Vec3> readVec3(int accessor, const char* semantic) const;
  // A SCALAR UNSIGNED_BYTE/SHORT/INT accessor of vertex indices, each below `vertexCount`.
  std::vector<std::uint32_t> readIndices(int accessor, std::size_t vertexCount) const;
  // The accessor's `count` (the vertex count of an attribute).
  std::size_t count(int accessor) const;

 private:
  struct Layout {
    const unsigned char* first = nullptr;  // element 0
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    std::string pointer;
  };
  Layout layout(int accessor, const char* expectedType, std::size_t componentSize) const;

  const nlohmann::json& document_;
  const GltfBuffers& buffers_;
  std::string file_;
};

}  // namespace scene_input
