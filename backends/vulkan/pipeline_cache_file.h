// A VkPipelineCache kept on disk between runs, so repeated runs (every ctest
// test is a new process) do not compile the same pipelines again. One file per
// device and driver build (the cache UUID is in the name); the driver checks
// the header of what it is given and ignores a stale file.
//
// The folder: $LIGHTCTS_CACHE_DIR, else $XDG_CACHE_HOME/lightcts, else
// $HOME/.cache/lightcts. Without any of them the cache lives in memory only.
#pragma once

#include "backends/vulkan/vulkan_device.h"

#include <filesystem>

namespace backends::vulkan {

std::filesystem::path lightctsCacheDirectory();

class PipelineCacheFile {
 public:
  explicit PipelineCacheFile(const VulkanDevice& device);

  const vk::raii::PipelineCache& cache() const { return cache_; }
  // Writes the cache back (imaging/atomic_file.h: to a temporary name, then
  // renamed, so parallel runs never read a half-written file). A cache that
  // cannot be written only costs time; it is not an error.
  void save() const;

 private:
  std::filesystem::path path_;
  vk::raii::PipelineCache cache_{nullptr};
};

}  // namespace backends::vulkan
