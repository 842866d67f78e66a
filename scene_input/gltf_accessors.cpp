#include "scene_input/gltf_accessors.h"

#include "scene_input/gltf_import.h"

#include <cmath>
#include <cstring>

namespace scene_input {

using namespace lighting;  // the model this folder reads scenes into
namespace {

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

std::size_t componentSize(int componentType) {
  switch (componentType) {
    case 5120: case kUnsignedByte: return 1;
    case 5122: case kUnsignedShort: return 2;
    default: return 4;
  }
}

std::size_t valueOr(const nlohmann::json& object, const char* key, std::size_t fallback) {
  const auto found = object.find(key);
  return found == object.end() ? fallback : found->get<std::size_t>();
}

}  // namespace

std::size_t GltfAccessors::count(int accessor) const {
  return document_["accessors"][std::size_t(accessor)]["count"].get<std::size_t>();
}

GltfAccessors::Layout GltfAccessors::layout(int accessor, const char* expectedType, std::size_t components) const {
  const nlohmann::json& a = document_["accessors"][std::size_t(accessor)];
  Layout out;
  out.pointer = "/accessors/" + std::to_string(accessor);
  const std::string type = a["type"].get<std::string>();
  if (type != expectedType) throw GltfError(file_, out.pointer + "/type", "expected " + std::string(expectedType) + " here, got " + type);
  if (a.contains("sparse")) {
    throw GltfError(file_, out.pointer + "/sparse", "sparse accessors are not read by lightcts; write the values out");
  }
  if (!a.contains("bufferView")) {
    throw GltfError(file_, out.pointer,
                    "the accessor has no bufferView (its data would come from an extension lightcts does not read)");
  }
  out.componentType = a["componentType"].get<int>();
  out.count = a["count"].get<std::size_t>();
  const std::size_t elementSize = components * componentSize(out.componentType);
  const std::size_t viewIndex = a["bufferView"].get<std::size_t>();
  const nlohmann::json& view = document_["bufferViews"][viewIndex];
  const std::string viewPointer = "/bufferViews/" + std::to_string(viewIndex);
  const std::size_t bufferIndex = view["buffer"].get<std::size_t>();
  const std::vector<unsigned char>& buffer = buffers_.at(bufferIndex);
  const std::size_t viewOffset = valueOr(view, "byteOffset", 0);
  const std::size_t viewLength = view["byteLength"].get<std::size_t>();
  // All values are below 2^40 (checkGltfJson), so these sums cannot overflow.
  if (viewOffset + viewLength > buffer.size()) {
    throw GltfError(file_, viewPointer,
                    "the buffer view (bytes " + std::to_string(viewOffset) + " to " + std::to_string(viewOffset + viewLength) +
                        ") runs past the end of buffer " + std::to_string(bufferIndex) + " (" +
                        std::to_string(buffer.size()) + " bytes)");
  }
  out.stride = valueOr(view, "byteStride", elementSize);
  if (out.stride < elementSize) {
    throw GltfError(file_, viewPointer + "/byteStride",
                    "byteStride " + std::to_string(out.stride) + " is smaller than the element (" +
                        std::to_string(elementSize) + " bytes) of accessor " + std::to_string(accessor));
  }
  const std::size_t offset = valueOr(a, "byteOffset", 0);
  // The last element ends at offset + stride * (count - 1) + elementSize;
  // count is checked against the view first, so the product cannot overflow.
  const bool fits = offset <= viewLength && (out.count - 1) <= (viewLength - offset) / out.stride &&
                    offset + out.stride * (out.count - 1) + elementSize <= viewLength;
  if (!fits) {
    throw GltfError(file_, out.pointer,
                    std::to_string(out.count) + " elements of " + std::to_string(elementSize) + " bytes, stride " +
                        std::to_string(out.stride) + ", from byte " + std::to_string(offset) +
                        " do not fit in buffer view " + std::to_string(viewIndex) + " (" + std::to_string(viewLength) +
                        " bytes)");
  }
  out.first = buffer.data() + viewOffset + offset;
  return out;
}

std::vector<Vec3> GltfAccessors::readVec3(int accessor, const char* semantic) const {
  const Layout l = layout(accessor, "VEC3", 3);
  if (l.componentType != kFloat) {
    throw GltfError(file_, l.pointer + "/componentType",
                    std::string(semantic) + " must be FLOAT (5126), got " + std::to_string(l.componentType));
  }
  std::vector<Vec3> values(l.count);
  for (std::size_t e = 0; e < l.count; ++e) {
    float xyz[3];
    std::memcpy(xyz, l.first + e * l.stride, sizeof xyz);
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(xyz[c])) {
        throw GltfError(file_, l.pointer,
                        std::string(semantic) + " element " + std::to_string(e) + " component " + std::to_string(c) +
                            " is not finite (" + std::to_string(xyz[c]) + ")");
      }
    }
    values[e] = Vec3(xyz[0], xyz[1], xyz[2]);
  }
  return values;
}

std::vector<std::uint32_t> GltfAccessors::readIndices(int accessor, std::size_t vertexCount) const {
  const Layout l = layout(accessor, "SCALAR", 1);
  if (l.componentType != kUnsignedByte && l.componentType != kUnsignedShort && l.componentType != kUnsignedInt) {
    throw GltfError(file_, l.pointer + "/componentType",
                    "indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got " + std::to_string(l.componentType));
  }
  std::vector<std::uint32_t> indices(l.count);
  for (std::size_t e = 0; e < l.count; ++e) {
    const unsigned char* at = l.first + e * l.stride;
    std::uint32_t value = 0;
    if (l.componentType == kUnsignedByte) {
      value = at[0];
    } else if (l.componentType == kUnsignedShort) {
      std::uint16_t v;
      std::memcpy(&v, at, 2);
      value = v;
    } else {
      std::memcpy(&value, at, 4);
    }
    if (value >= vertexCount) {
      throw GltfError(file_, l.pointer,
                      "index " + std::to_string(value) + " (element " + std::to_string(e) +
                          ") is out of range: the primitive has " + std::to_string(vertexCount) + " vertices");
    }
    indices[e] = value;
  }
  return indices;
}

}  // namespace scene_input
