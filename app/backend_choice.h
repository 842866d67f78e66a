// Turning --backend, --device, --driver and the test-only shader options into
// a running backend. Unknown names are usage errors (exit 2); a SPEC backend
// this build or machine lacks is a skip (exit 3), never a pass.
#pragma once

#include "app/commands.h"
#include "backends/backend.h"
#include "lighting/light_clusters.h"

#include <memory>
#include <optional>
#include <ostream>

namespace app {

// Null with `status` set (and a message on `err`) when the name is unknown
// or not built.
const backends::BackendEntry* resolveBackend(const std::string& name, std::ostream& err, int& status);

// The options a command's arguments ask for. Throws InputError for an
// unknown mutant.
backends::BackendOptions backendOptions(const BackendArguments& args);

// The cluster grid of --mode clustered; nullopt for the model's mode.
std::optional<lighting::ClusterGridSpec> clusteredMode(const BackendArguments& args);
// Throws InputError when --mode cannot draw `frame` (the clustered mode:
// legacy, deferred, per-object lists; lighting::clusteredModeRefusal).
void checkModeDraws(const lighting::Frame& frame, const BackendArguments& args);
// `frame` as --mode draws it: the model's frame, or its clustered form.
// Throws InputError as checkModeDraws does, or for a grid below 1.
lighting::Frame frameInMode(lighting::Frame frame, const BackendArguments& args);

// The test's name for this scene and backend: <group>.<name>.<backend> (SPEC 10),
// with the group the scene file's folder.
std::string caseName(const std::string& scenePath, const BackendArguments& args);

}  // namespace app
