// The `lightcts` subcommands (SPEC 8). main.cpp only parses arguments and calls
// these; each returns an exit status (exit_status.h) and reports errors on
// `err` with a message a user can act on.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace app {

struct SceneArguments {
  std::string scenePath;
  int frame = 0;
};

int runBackendsCommand(std::ostream& out, std::ostream& err);
int runLightsCommand(const SceneArguments& args, std::ostream& out, std::ostream& err);
int runReferenceCommand(const SceneArguments& args, bool ideal, const std::string& outDir,
                        std::ostream& out, std::ostream& err);

struct BackendArguments {
  std::string backend{};
  std::string device{};
  std::string driver{};
  // Test-only extensions of SPEC 8 (docs/cli.md): a deliberately wrong
  // variant of the model (shaders/shader_variant.h), or every shader feature
  // on whatever the scene uses.
  std::string mutant = "none";
  bool fullShader = false;
};
int runRenderCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& outFile,
                     std::ostream& out, std::ostream& err);
// Evidence of a failure goes to `evidenceDir`, or when empty to
// lightcts-evidence/<group>.<name>.<backend> under the current folder.
int runCompareCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& evidenceDir,
                      std::ostream& out, std::ostream& err);
int runSuiteCommand(const std::vector<std::string>& backends, const std::string& scenesDir,
                    const std::string& outDir, std::ostream& out, std::ostream& err);

}  // namespace app
