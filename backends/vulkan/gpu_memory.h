// Buffers and images with their own memory. lightcts draws a handful of small
// objects, so one allocation per resource is enough and no allocator library
// earns its place. Buffers are host-visible and stay mapped: the CPU writes
// uniforms and vertices straight into them and reads the readback from one.
#pragma once

#include "backends/vulkan/vulkan_device.h"

#include <cstdint>
#include <cstring>
#include <span>

namespace backends::vulkan {

struct HostBuffer {
  HostBuffer(const VulkanDevice& device, vk::DeviceSize size, vk::BufferUsageFlags usage);

  vk::raii::Buffer buffer{nullptr};
  vk::raii::DeviceMemory memory{nullptr};
  vk::DeviceSize size = 0;
  void* mapped = nullptr;

  template <class T>
  void write(std::span<const T> data, vk::DeviceSize offset = 0) {
    std::memcpy(static_cast<char*>(mapped) + offset, data.data(), data.size_bytes());
  }
};

// A flat image has one layer; a cube has six (+X, -X, +Y, -Y, +Z, -Z) and a
// cube view.
enum class ImageShape { Flat, Cube };

struct DeviceImage {
  DeviceImage(const VulkanDevice& device, vk::Format format, vk::Extent2D extent, vk::ImageUsageFlags usage,
              vk::ImageAspectFlags aspect, ImageShape shape = ImageShape::Flat);

  vk::raii::Image image{nullptr};
  vk::raii::DeviceMemory memory{nullptr};
  vk::raii::ImageView view{nullptr};
  vk::Format format;
  vk::Extent2D extent;
  std::uint32_t layers = 1;
};

}  // namespace backends::vulkan
