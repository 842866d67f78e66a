// The distance between consecutive blocks of one uniform buffer bound at
// per-draw offsets: the block's size rounded up to the driver's offset
// alignment (Vulkan's minUniformBufferOffsetAlignment, GL's
// GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT). Both backends lay out their object and
// light blocks with it.
#pragma once

#include <cstddef>

namespace backends {

constexpr std::size_t alignedStride(std::size_t blockSize, std::size_t alignment) {
  return (blockSize + alignment - 1) / alignment * alignment;
}

}  // namespace backends
