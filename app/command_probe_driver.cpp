// The hidden `lightcts probe-driver --backend B --driver D` that `lightcts
// backends` starts for each GL driver (backends/gl/probe_in_child.h): it
// creates the backend on that driver and writes what it found, in the
// probe's line format, on standard output.
#include "app/commands.h"
#include "app/exit_status.h"
#include "backends/backend.h"
#include "backends/gl/probe_in_child.h"

#include <unistd.h>

#include <cstdlib>
#include <ostream>
#include <string_view>

namespace app {

int runProbeDriverCommand(const std::string& backend, const std::string& driver, std::ostream& out,
                          std::ostream& err) {
  // Test hook (docs/cli.md): a probe that hangs, as a hung driver would.
  if (const char* hang = std::getenv("LIGHTCTS_TEST_PROBE_HANG"); hang && std::string_view(hang) == "1")
    for (;;) ::pause();
  out << backends::gl::probeAnswer([&] {
    const backends::BackendEntry* entry = backends::findBuiltBackendEntry(backend);
    if (!entry) throw backends::NotSupportedError("backend '" + backend + "' is not built");
    backends::BackendOptions options;
    options.driver = driver;
    return entry->create(options)->device();
  });
  out.flush();
  (void)err;
  return kExitSuccess;
}

}  // namespace app
