#include "backends/vulkan/pipeline_cache_file.h"

#include "imaging/atomic_file.h"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string_view>
#include <vector>

namespace backends::vulkan {
namespace {

std::filesystem::path cacheFileName(const vk::PhysicalDeviceProperties& p) {
  std::ostringstream name;
  name << "vulkan-pipelines-" << std::hex << std::setfill('0') << std::setw(4) << p.vendorID << "-" << std::setw(4)
       << p.deviceID << "-";
  for (std::uint8_t byte : p.pipelineCacheUUID) name << std::setw(2) << int(byte);
  name << ".bin";
  return name.str();
}

std::vector<char> readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

std::filesystem::path lightctsCacheDirectory() {
  if (const char* dir = std::getenv("LIGHTCTS_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "lightcts";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "lightcts";
  return {};
}

PipelineCacheFile::PipelineCacheFile(const VulkanDevice& device) {
  const std::filesystem::path dir = lightctsCacheDirectory();
  if (!dir.empty()) path_ = dir / cacheFileName(device.physical.getProperties());
  const std::vector<char> data = path_.empty() ? std::vector<char>{} : readFile(path_);
  try {
    cache_ = vk::raii::PipelineCache(device.device,
                                     vk::PipelineCacheCreateInfo{.initialDataSize = data.size(), .pInitialData = data.data()});
  } catch (const vk::SystemError&) {
    // A damaged file: start empty rather than fail the render.
    cache_ = vk::raii::PipelineCache(device.device, vk::PipelineCacheCreateInfo{});
  }
}

void PipelineCacheFile::save() const {
  if (path_.empty()) return;
  try {
    const std::vector<std::uint8_t> data = cache_.getData();
    imaging::writeFileAtomically(path_,
                                 std::string_view(reinterpret_cast<const char*>(data.data()), data.size()));
  } catch (const std::exception&) {
    // Not being able to keep the cache only costs compile time next run.
  }
}

}  // namespace backends::vulkan
