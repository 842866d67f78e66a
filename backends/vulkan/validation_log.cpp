#include "backends/vulkan/validation_log.h"

#include "backends/backend.h"

namespace backends::vulkan {

vk::DebugUtilsMessengerCreateInfoEXT ValidationLog::messengerCreateInfo() {
  using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
  using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
  return vk::DebugUtilsMessengerCreateInfoEXT{
      .messageSeverity = Severity::eWarning | Severity::eError,
      .messageType = Type::eGeneral | Type::eValidation | Type::ePerformance,
      .pfnUserCallback = &ValidationLog::callback,
      .pUserData = this,
  };
}

VkBool32 ValidationLog::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* log = static_cast<ValidationLog*>(user);
  std::string text = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error: " : "warning: ";
  text += data && data->pMessage ? data->pMessage : "(no message)";
  std::lock_guard lock(log->mutex_);
  log->messages_.push_back(std::move(text));
  return VK_FALSE;  // never abort the call: the render fails afterwards with the whole log
}

void ValidationLog::throwIfAny(const std::string& when) {
  std::lock_guard lock(mutex_);
  if (messages_.empty()) return;
  std::string text = "Vulkan validation reported " + std::to_string(messages_.size()) + " message(s) while " + when + ":";
  for (const std::string& m : messages_) text += "\n  " + m;
  messages_.clear();
  throw DriverError(text);
}

}  // namespace backends::vulkan
