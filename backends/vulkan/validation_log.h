// Collects what VK_LAYER_KHRONOS_validation says through VK_EXT_debug_utils.
// Any message fails the render (SPEC: no validation message is acceptable in
// a Vulkan test run): the backend checks the log after every submission.
#pragma once

#include "backends/vulkan/vulkan_api.h"

#include <mutex>
#include <string>
#include <vector>

namespace backends::vulkan {

class ValidationLog {
 public:
  // The create info for a messenger (or an instance's pNext) that reports
  // warnings and errors of every type into this log.
  vk::DebugUtilsMessengerCreateInfoEXT messengerCreateInfo();

  // Throws DriverError listing the messages, if any arrived; `when` says
  // what the backend was doing.
  void throwIfAny(const std::string& when);

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  std::mutex mutex_;  // the layer may call from driver threads
  std::vector<std::string> messages_;
};

}  // namespace backends::vulkan
