// The interface every rendering backend implements, and the registry of the
// backends compiled into this build. A backend renders a prepared Frame (the
// lights were chosen on the CPU, lighting/frame.h) and reads back an RGBA float
// image with row 0 at the top; it never decides which lights count.
#pragma once

#include "imaging/image.h"
#include "lighting/frame.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace backends {

// The backend names of SPEC 8. A name outside this list is a usage error
// (exit 2); a name in it that this build or machine lacks is a skip (exit 3).
const std::vector<std::string>& specBackendNames();

struct DeviceInfo {
  std::string name;
  std::string driver;
  std::string driverVersion;
  std::string apiVersion;
};

struct BackendOptions {
  std::string device;  // --device: index or name substring; empty for the default
  std::string driver;  // --driver (GL backends): llvmpipe | softpipe
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual DeviceInfo device() const = 0;
  virtual imaging::Image render(const lighting::Frame& frame) = 0;
};

struct BackendEntry {
  std::string name;
  std::function<std::vector<DeviceInfo>(const BackendOptions&)> listDevices;
  std::function<std::unique_ptr<Backend>(const BackendOptions&)> create;
};

// The backends compiled in (none until the Vulkan and OpenGL backends land).
const std::vector<BackendEntry>& compiledBackends();
const BackendEntry* findCompiledBackend(const std::string& name);

}  // namespace backends
