#include "backends/vulkan/gpu_memory.h"

namespace backends::vulkan {

HostBuffer::HostBuffer(const VulkanDevice& device, vk::DeviceSize bytes, vk::BufferUsageFlags usage) : size(bytes) {
  buffer = vk::raii::Buffer(device.device, vk::BufferCreateInfo{.size = bytes, .usage = usage,
                                                                .sharingMode = vk::SharingMode::eExclusive});
  const vk::MemoryRequirements needs = buffer.getMemoryRequirements();
  // Coherent, so no flush or invalidate is needed around the fence waits.
  const auto properties = vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent;
  memory = vk::raii::DeviceMemory(
      device.device,
      vk::MemoryAllocateInfo{.allocationSize = needs.size, .memoryTypeIndex = device.memoryType(needs.memoryTypeBits, properties)});
  buffer.bindMemory(*memory, 0);
  mapped = memory.mapMemory(0, VK_WHOLE_SIZE);
}

DeviceImage::DeviceImage(const VulkanDevice& device, vk::Format imageFormat, vk::Extent2D imageExtent,
                         vk::ImageUsageFlags usage, vk::ImageAspectFlags aspect, ImageShape shape)
    : format(imageFormat), extent(imageExtent), layers(shape == ImageShape::Cube ? 6 : 1) {
  const bool cube = shape == ImageShape::Cube;
  image = vk::raii::Image(device.device, vk::ImageCreateInfo{
                                             .flags = cube ? vk::ImageCreateFlagBits::eCubeCompatible
                                                           : vk::ImageCreateFlags{},
                                             .imageType = vk::ImageType::e2D,
                                             .format = format,
                                             .extent = vk::Extent3D{extent.width, extent.height, 1},
                                             .mipLevels = 1,
                                             .arrayLayers = layers,
                                             .samples = vk::SampleCountFlagBits::e1,
                                             .tiling = vk::ImageTiling::eOptimal,
                                             .usage = usage,
                                             .sharingMode = vk::SharingMode::eExclusive,
                                             .initialLayout = vk::ImageLayout::eUndefined,
                                         });
  const vk::MemoryRequirements needs = image.getMemoryRequirements();
  memory = vk::raii::DeviceMemory(
      device.device, vk::MemoryAllocateInfo{.allocationSize = needs.size,
                                            .memoryTypeIndex = device.memoryType(needs.memoryTypeBits,
                                                                                 vk::MemoryPropertyFlagBits::eDeviceLocal)});
  image.bindMemory(*memory, 0);
  view = vk::raii::ImageView(device.device, vk::ImageViewCreateInfo{
                                                .image = *image,
                                                .viewType = cube ? vk::ImageViewType::eCube : vk::ImageViewType::e2D,
                                                .format = format,
                                                .subresourceRange = {aspect, 0, 1, 0, layers},
                                            });
}

}  // namespace backends::vulkan
