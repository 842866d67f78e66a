#include "backends/gl/gl_context.h"
#include "backends/vulkan/vulkan_drivers.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>

namespace backends::gl {
namespace {

// Gallium drivers that Mesa's software path (drisw, OSMesa) loads by name.
// zink draws through Vulkan (on lavapipe where there is no GPU), but Mesa
// reaches it through the same path.
bool softwarePathDriver(const std::string& driver) {
  return driver == "llvmpipe" || driver == "softpipe" || driver == "swr" || driver == "zink";
}

// Drivers whose GL_RENDERER names the driver they run on as well as
// themselves: "zink (llvmpipe (LLVM 15.0.6, 256 bits))".
bool layeredDriver(const std::string& word) { return word == "zink" || word == "virgl" || word == "d3d12"; }

bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `word` is in `text` as a whole word.
bool containsWord(const std::string& text, const std::string& word) {
  for (std::size_t pos = 0; (pos = text.find(word, pos)) != std::string::npos; ++pos) {
    const std::size_t end = pos + word.size();
    if ((pos == 0 || !wordChar(text[pos - 1])) && (end == text.size() || !wordChar(text[end]))) return true;
  }
  return false;
}

}  // namespace

std::string requestedMesaDriver(const BackendOptions& options) {
  return options.driver.empty() ? "llvmpipe" : options.driver;
}

bool validMesaDriverName(const std::string& driver) {
  if (driver.empty() || driver.size() > 64) return false;
  for (char c : driver)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

void selectMesaDriver(const std::string& driver) {
  // GALLIUM_DRIVER names the driver either way. For Mesa's software path,
  // LIBGL_ALWAYS_SOFTWARE keeps Mesa from picking a hardware driver where one
  // exists; any other name is a hardware driver, which the DRI loader picks
  // by MESA_LOADER_DRIVER_OVERRIDE (and which the software path would refuse).
  ::setenv("GALLIUM_DRIVER", driver.c_str(), 1);
  if (softwarePathDriver(driver)) {
    ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    ::unsetenv("MESA_LOADER_DRIVER_OVERRIDE");
  } else {
    ::unsetenv("LIBGL_ALWAYS_SOFTWARE");
    ::setenv("MESA_LOADER_DRIVER_OVERRIDE", driver.c_str(), 1);
  }
}

std::unique_ptr<ScopedEnvironment> pinVulkanDriverUnder(const std::string& driver) {
  if (driver != "zink") return nullptr;
  const vulkan::NamedVulkanDriver& lavapipe = vulkan::lavapipeDriver();
  if (!std::filesystem::exists(lavapipe.manifest))
    throw NotSupportedError("zink runs only on lavapipe, and lavapipe's Vulkan driver is not installed (no " +
                            lavapipe.manifest + "; Debian's " + lavapipe.package + " package installs it)");
  auto variables = vulkan::onlyDriverVariables(lavapipe.manifest);
  // The layer's own switch (its manifest's disable_environment).
  variables.emplace_back("NODEVICE_SELECT", "1");
  return std::make_unique<ScopedEnvironment>(variables);
}

bool rendererRunsOn(const std::string& renderer, const std::string& driver) {
  std::string text;
  for (char c : renderer) text += char(std::tolower(static_cast<unsigned char>(c)));
  std::size_t firstEnd = 0;
  while (firstEnd < text.size() && wordChar(text[firstEnd])) ++firstEnd;
  const std::string first = text.substr(0, firstEnd);
  // "zink (llvmpipe ...)" runs on zink, not on llvmpipe; and on
  // lavapipe (device llvmpipe), the one Vulkan driver zink is given.
  if (layeredDriver(first))
    return first == driver && (driver != "zink" || containsWord(text.substr(firstEnd), "llvmpipe"));
  return containsWord(text, driver);
}

std::string describeMesaDriver(const std::string& driver) {
  return driver == "zink" ? "zink on lavapipe" : driver;
}

}  // namespace backends::gl
