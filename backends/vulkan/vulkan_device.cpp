#include "backends/vulkan/vulkan_device.h"

#include "backends/scoped_environment.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <sstream>

namespace backends::vulkan {
namespace {

constexpr std::uint32_t kRequiredApiVersion = VK_API_VERSION_1_3;  // dynamic rendering, synchronization2
constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr std::uint32_t kNvidiaVendorId = 0x10DE;

std::string versionString(std::uint32_t v) {
  std::ostringstream s;
  s << VK_API_VERSION_MAJOR(v) << "." << VK_API_VERSION_MINOR(v) << "." << VK_API_VERSION_PATCH(v);
  return s.str();
}

// Drivers encode their version as they like; NVIDIA's is 10.8.8.6 bits, the
// others (Mesa among them) use VK_MAKE_API_VERSION.
std::string driverVersionString(std::uint32_t vendor, std::uint32_t v) {
  if (vendor != kNvidiaVendorId) return versionString(v);
  std::ostringstream s;
  s << (v >> 22) << "." << ((v >> 14) & 0xFF) << "." << ((v >> 6) & 0xFF) << "." << (v & 0x3F);
  return s.str();
}

bool layerInstalled(const vk::raii::Context& context, const char* name) {
  for (const vk::LayerProperties& layer : context.enumerateInstanceLayerProperties())
    if (std::string_view(layer.layerName.data()) == name) return true;
  return false;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

const NamedVulkanDriver* namedDriver(const std::string& name) {
  if (name.empty()) return nullptr;
  const NamedVulkanDriver* driver = findNamedVulkanDriver(name);
  if (!driver)
    throw NotSupportedError("Vulkan has no driver named '" + name + "' (--driver on Vulkan: " +
                            namedVulkanDriverList() + ")");
  if (!std::filesystem::exists(driver->manifest))
    throw NotSupportedError(driver->title + "'s Vulkan driver is not installed (no " + driver->manifest +
                            "; Debian's " + driver->package + " package installs it)");
  return driver;
}

}  // namespace

VulkanInstance::VulkanInstance(bool validation, const std::string& driver) try
    : log_(std::make_unique<ValidationLog>()), driver_(namedDriver(driver)) {
  if (context_.enumerateInstanceVersion() < kRequiredApiVersion)
    throw NotSupportedError("the Vulkan loader is older than 1.3");
  validating_ = validation && layerInstalled(context_, kValidationLayer);

  const vk::ApplicationInfo app{.pApplicationName = "lightcts", .apiVersion = kRequiredApiVersion};
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  // Synchronisation validation catches a missing barrier before the readback.
  const vk::ValidationFeatureEnableEXT enables[] = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
  vk::ValidationFeaturesEXT features{.enabledValidationFeatureCount = 1, .pEnabledValidationFeatures = enables};
  vk::DebugUtilsMessengerCreateInfoEXT messengerInfo = log_->messengerCreateInfo();
  if (validating_) {
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    // Chained into the instance info, the messenger also hears instance creation.
    messengerInfo.pNext = &features;
  }
  const vk::InstanceCreateInfo info{
      .pNext = validating_ ? &messengerInfo : nullptr,
      .pApplicationInfo = &app,
      .enabledLayerCount = std::uint32_t(layers.size()),
      .ppEnabledLayerNames = layers.data(),
      .enabledExtensionCount = std::uint32_t(extensions.size()),
      .ppEnabledExtensionNames = extensions.data(),
  };
  {
    // The loader reads its driver list when the instance is created; the
    // environment is put back after, so a later instance of the same process
    // sees the loader's own choice again.
    std::optional<ScopedEnvironment> onlyThisDriver;
    if (driver_) onlyThisDriver.emplace(onlyDriverVariables(driver_->manifest));
    instance_ = vk::raii::Instance(context_, info);
  }
  if (validating_) messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, log_->messengerCreateInfo());
} catch (const vk::IncompatibleDriverError&) {
  throw NotSupportedError("no Vulkan driver is installed (VK_ERROR_INCOMPATIBLE_DRIVER)");
} catch (const vk::SystemError& e) {
  throw DriverError(std::string("creating the Vulkan instance failed: ") + e.what());
} catch (const NotSupportedError&) {
  throw;
} catch (const std::runtime_error& e) {
  // vk::raii::Context throws this when libvulkan.so.1 cannot be opened.
  throw NotSupportedError(std::string("the Vulkan loader is not available: ") + e.what());
}

std::vector<vk::raii::PhysicalDevice> VulkanInstance::physicalDevices() const {
  std::vector<vk::raii::PhysicalDevice> devices;
  for (vk::raii::PhysicalDevice& d : vk::raii::PhysicalDevices(instance_)) {
    if (d.getProperties().apiVersion < kRequiredApiVersion) continue;
    if (driver_ && d.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>()
                           .get<vk::PhysicalDeviceDriverProperties>()
                           .driverID != driver_->driverId)
      continue;
    devices.push_back(std::move(d));
  }
  if (driver_ && devices.empty())
    throw NotSupportedError(driver_->manifest + " gave no Vulkan 1.3 device that reports " + driver_->title +
                            "'s driver ID");
  return devices;
}

DeviceInfo describeDevice(const vk::raii::PhysicalDevice& device) {
  const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>();
  const vk::PhysicalDeviceProperties& p = chain.get<vk::PhysicalDeviceProperties2>().properties;
  const vk::PhysicalDeviceDriverProperties& d = chain.get<vk::PhysicalDeviceDriverProperties>();
  DeviceInfo info;
  info.name = p.deviceName.data();
  info.driver = std::string(d.driverName.data()) + " (" + d.driverInfo.data() + ")";
  info.driverVersion = driverVersionString(p.vendorID, p.driverVersion);
  info.apiVersion = versionString(p.apiVersion);
  info.subTexelPrecisionBits = int(p.limits.subTexelPrecisionBits);
  info.subPixelPrecisionBits = int(p.limits.subPixelPrecisionBits);
  return info;
}

std::size_t chooseDevice(const std::vector<DeviceInfo>& devices, const std::string& selector) {
  if (devices.empty()) throw NotSupportedError("no Vulkan 1.3 device is present");
  if (selector.empty()) return 0;
  const bool isIndex = std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); });
  if (isIndex) {
    const std::size_t index = std::stoul(selector);
    if (index < devices.size()) return index;
  } else {
    for (std::size_t i = 0; i < devices.size(); ++i)
      if (lower(devices[i].name).find(lower(selector)) != std::string::npos) return i;
  }
  std::string text = "no Vulkan device matches --device '" + selector + "'; present:";
  for (std::size_t i = 0; i < devices.size(); ++i) text += " [" + std::to_string(i) + "] " + devices[i].name;
  throw NotSupportedError(text);
}

VulkanDevice::VulkanDevice(const VulkanInstance& instance, const std::string& selector) {
  std::vector<vk::raii::PhysicalDevice> candidates = instance.physicalDevices();
  std::vector<DeviceInfo> infos;
  for (const auto& c : candidates) infos.push_back(describeDevice(c));
  const std::size_t chosen = chooseDevice(infos, selector);
  info = infos[chosen];
  physical = std::move(candidates[chosen]);
  limits = physical.getProperties().limits;

  const auto families = physical.getQueueFamilyProperties();
  const auto graphics = std::find_if(families.begin(), families.end(), [](const vk::QueueFamilyProperties& f) {
    return bool(f.queueFlags & vk::QueueFlagBits::eGraphics);
  });
  if (graphics == families.end()) throw NotSupportedError(info.name + " has no graphics queue");
  queueFamily = std::uint32_t(graphics - families.begin());
  timestampValidBits = graphics->timestampValidBits;

  const float priority = 1.0f;
  const vk::DeviceQueueCreateInfo queueInfo{.queueFamilyIndex = queueFamily, .queueCount = 1, .pQueuePriorities = &priority};
  depthClamp = physical.getFeatures().depthClamp == VK_TRUE;
  const vk::PhysicalDeviceFeatures features{.depthClamp = depthClamp ? VK_TRUE : VK_FALSE};
  vk::PhysicalDeviceVulkan13Features features13{.synchronization2 = VK_TRUE, .dynamicRendering = VK_TRUE};
  const vk::DeviceCreateInfo deviceInfo{.pNext = &features13,
                                        .queueCreateInfoCount = 1,
                                        .pQueueCreateInfos = &queueInfo,
                                        .pEnabledFeatures = &features};
  try {
    device = vk::raii::Device(physical, deviceInfo);
  } catch (const vk::SystemError& e) {
    throw DriverError("creating a Vulkan device on " + info.name + " failed: " + e.what());
  }
  queue = vk::raii::Queue(device, queueFamily, 0);
}

std::uint32_t VulkanDevice::memoryType(std::uint32_t typeBits, vk::MemoryPropertyFlags properties) const {
  const vk::PhysicalDeviceMemoryProperties memory = physical.getMemoryProperties();
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
  throw DriverError(info.name + " has no memory type with the properties a lightcts buffer needs");
}

}  // namespace backends::vulkan
