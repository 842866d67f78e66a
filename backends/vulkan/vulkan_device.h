// Instance and device without a surface (headless), and the choice of device
// by `--device`: an index into the list `lightcts backends` prints, or a
// substring of the device name; the first device by default.
#pragma once

#include "backends/backend.h"
#include "backends/vulkan/validation_log.h"
#include "backends/vulkan/vulkan_api.h"
#include "backends/vulkan/vulkan_drivers.h"

#include <memory>
#include <string>
#include <vector>

namespace backends::vulkan {

class VulkanInstance {
 public:
  // Throws NotSupportedError when there is no Vulkan loader or no Vulkan 1.3
  // instance. With `validation`, VK_LAYER_KHRONOS_validation is enabled when
  // installed (synchronisation checks included) and its messages are logged.
  // `driver` (--driver) names a driver of vulkan_drivers.h: the instance
  // loads that driver's manifest alone, and NotSupportedError says so when
  // it is not installed or is unknown; empty, the loader's own choice.
  explicit VulkanInstance(bool validation, const std::string& driver = "");

  const vk::raii::Instance& instance() const { return instance_; }
  // The Vulkan 1.3 devices; with a named driver, only those that report its
  // VkDriverId (NotSupportedError when none does).
  std::vector<vk::raii::PhysicalDevice> physicalDevices() const;
  // Null when validation is off or the layer is not installed.
  ValidationLog* validationLog() { return validating_ ? log_.get() : nullptr; }

 private:
  std::unique_ptr<ValidationLog> log_;  // outlives the messenger that points at it
  bool validating_ = false;
  const NamedVulkanDriver* driver_ = nullptr;
  vk::raii::Context context_;
  vk::raii::Instance instance_{nullptr};
  vk::raii::DebugUtilsMessengerEXT messenger_{nullptr};
};

DeviceInfo describeDevice(const vk::raii::PhysicalDevice& device);

// The index of the device `selector` names (empty: 0). Throws
// NotSupportedError, listing what is there, when nothing matches.
std::size_t chooseDevice(const std::vector<DeviceInfo>& devices, const std::string& selector);

// The logical device and its one graphics queue.
struct VulkanDevice {
  VulkanDevice(const VulkanInstance& instance, const std::string& selector);

  DeviceInfo info;
  vk::raii::PhysicalDevice physical{nullptr};
  vk::PhysicalDeviceLimits limits;
  std::uint32_t queueFamily = 0;
  std::uint32_t timestampValidBits = 0;  // of the queue family; 0: it writes no timestamps
  // depthClamp is enabled whenever the device has it: the deferred light pass
  // clamps volumes that reach past the far plane instead of clipping them.
  bool depthClamp = false;
  vk::raii::Device device{nullptr};
  vk::raii::Queue queue{nullptr};

  // A memory type allowed by `typeBits` with `properties`; throws DriverError if none.
  std::uint32_t memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags properties) const;
};

}  // namespace backends::vulkan
