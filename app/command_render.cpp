// `lightcts render` and `lightcts compare` (SPEC 8).
#include "app/backend_choice.h"
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "comparison/comparison_report.h"
#include "imaging/image_files.h"
#include "reference/reference_renderer.h"

#include <filesystem>
#include <ostream>

namespace app {
namespace {

// The scene is checked first: a bad scene is exit 2 whatever the backend.
struct Rendered {
  SceneInput input;
  imaging::Image image;
};

int renderOnBackend(const SceneArguments& args, const BackendArguments& backend, std::ostream& err,
                    Rendered& rendered) {
  rendered.input = loadSceneInput(args);
  int status = kExitSuccess;
  const backends::BackendEntry* entry = resolveBackend(backend.backend, err, status);
  if (!entry) return status;
  const backends::BackendOptions options = backendOptions(backend);
  std::unique_ptr<backends::Backend> renderer = entry->create(options);
  rendered.image = renderer->render(rendered.input.frame);
  return kExitSuccess;
}

}  // namespace

int runRenderCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& outFile,
                     std::ostream&, std::ostream& err) {
  return guardCommand(err, [&] {
    Rendered rendered;
    if (int status = renderOnBackend(args, backend, err, rendered); status != kExitSuccess) return status;
    const std::filesystem::path parent = std::filesystem::path(outFile).parent_path();
    if (!parent.empty()) makeOutputDirectory(parent.string());
    imaging::writeExr(outFile, rendered.image);
    return kExitSuccess;
  });
}

int runCompareCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& evidenceDir,
                      std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    Rendered rendered;
    if (int status = renderOnBackend(args, backend, err, rendered); status != kExitSuccess) return status;
    const reference::ReferenceRenderer referenceRenderer(rendered.input.prepared);
    const reference::ReferenceImages ref = referenceRenderer.render(rendered.input.frame);
    const lighting::Expectation& expect = rendered.input.prepared->scene.expect;
    const comparison::Comparison result = comparison::compareImages(rendered.image, ref, expect);

    const std::string name = caseName(args.scenePath, backend);
    comparison::printComparison(out, result, name);
    if (result.verdict == comparison::Verdict::Pass) return kExitSuccess;
    const std::string dir = evidenceDir.empty() ? "lightcts-evidence/" + name : evidenceDir;
    comparison::writeEvidence(dir, result, rendered.image, ref, name);
    out << "evidence: " << dir << "\n";
    return kExitConformanceFailure;
  });
}

}  // namespace app
