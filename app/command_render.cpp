// `lightcts render` and `lightcts compare` (SPEC 8).
#include "app/backend_choice.h"
#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "backends/expected_driver.h"
#include "comparison/comparison_report.h"
#include "conformance/cpu_mutants.h"
#include "conformance/reference_cache.h"
#include "conformance/scene_check.h"
#include "imaging/image_codec_loader.h"
#include "imaging/image_files.h"
#include "reference/reference_renderer.h"

#include <cmath>
#include <filesystem>
#include <ostream>

namespace app {
namespace {

// The scene is checked first: a bad scene is exit 2 whatever the backend.
struct Rendered {
  SceneInput input;
  imaging::Image image;
};

// Builds the backend the arguments ask for and checks it is the driver asked
// for (--expect-driver). Returns an exit status; kExitSuccess sets `backend`.
int createBackend(const BackendArguments& args, std::ostream& err, std::unique_ptr<backends::Backend>& backend) {
  int status = kExitSuccess;
  const backends::BackendEntry* entry = resolveBackend(args.backend, err, status);
  if (!entry) return status;
  backend = entry->create(backendOptions(args));
  backends::requireExpectedDriver(backend->device(), args.expectDriver);
  return kExitSuccess;
}

int renderOnBackend(const SceneArguments& args, const BackendArguments& backend, std::ostream& err,
                    Rendered& rendered) {
  rendered.input = loadSceneInput(args);
  std::unique_ptr<backends::Backend> renderer;
  if (int status = createBackend(backend, err, renderer); status != kExitSuccess) return status;
  // A CPU mutant alters the frame, as `compare` does (conformance/cpu_mutants.h).
  const shaders::Mutant mutant = backendOptions(backend).variant.mutant;
  rendered.image = renderer->render(frameInMode(conformance::cpuMutantFrame(rendered.input.frame, mutant), backend));
  return kExitSuccess;
}

}  // namespace

int runRenderCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& outFile,
                     std::ostream&, std::ostream& err) {
  return guardCommand(err, [&] {
    Rendered rendered;
    if (int status = renderOnBackend(args, backend, err, rendered); status != kExitSuccess) return status;
    const std::filesystem::path parent = std::filesystem::path(outFile).parent_path();
    imaging::requireImageModule();
    if (!parent.empty()) makeOutputDirectory(parent.string());
    imaging::writeExr(outFile, rendered.image);
    return kExitSuccess;
  });
}

int runCompareCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& evidenceDir,
                      bool writeEvidence, std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    const SceneInput input = loadSceneInput(args);
    checkModeDraws(input.frame, backend);  // a scene the mode cannot draw is bad input (exit 2), before any driver
    std::unique_ptr<backends::Backend> renderer;
    if (int status = createBackend(backend, err, renderer); status != kExitSuccess) return status;
    // Every frame of an animated scene unless --frame picks one (SPEC 10:
    // popping-64's kept set is checked per frame).
    // The references come from the shared cache when another command or
    // run (ctest's other combinations) computed them already.
    conformance::SceneReferences references(
        input.prepared, conformance::referenceCaching(conformance::defaultReferenceCacheDirectory(), args.scenePath,
                                                      input.prepared->scene));
    conformance::CheckOptions options;
    if (args.frameGiven) options.onlyFrame = args.frame;
    options.mutant = backendOptions(backend).variant.mutant;
    options.clustered = clusteredMode(backend);
    const conformance::SceneCheck check = conformance::checkScene(references, *renderer, options);

    const std::string name = caseName(args.scenePath, backend);
    if (check.frames.size() > 1) {
      for (const conformance::FrameCheck& f : check.frames) {
        out << "  frame " << f.frame << ": ";
        comparison::printComparison(out, f.comparison, name);
      }
      if (check.poppingScore) out << "popping score " << *check.poppingScore << " (SPEC 6, against --ideal)\n";
    }
    // The worst pixels of the evidence frame (the first failing, else the
    // tightest); for one frame this is the whole report.
    if (check.frames.size() > 1)
      out << comparison::verdictName(check.verdict) << " " << name << ": " << check.frames.size()
          << " frames; frame " << check.evidenceFrame << " in detail:\n  ";
    comparison::printComparison(out, check.evidence().comparison, name);
    // SPEC 3.9: what the map's resolution and filter cost against exact shadows.
    if (check.frames.size() == 1 && !std::isnan(check.frames.front().idealError))
      out << "  error against ray-traced shadows (--ideal, information, not a verdict): "
          << check.frames.front().idealError << '\n';
    if (check.verdict == comparison::Verdict::QualityWarning &&
        check.evidence().comparison.verdict != comparison::Verdict::QualityWarning)
      out << "  QualityWarning: " << check.qualityWarning << " (SPEC 7: a comparison must be able to fail)\n";
    // A QualityWarning is no conformance failure (exit 0, docs/cli.md), and
    // no evidence: the frame showed nothing to look at.
    if (check.verdict != comparison::Verdict::Fail) return kExitSuccess;
    if (!writeEvidence) return kExitConformanceFailure;
    const std::string dir = evidenceDir.empty() ? "lightcts-evidence/" + name : evidenceDir;
    imaging::requireImageModule();  // the evidence is images: no half-written folder without it
    comparison::writeEvidence(dir, check.evidence().comparison, check.evidenceResult, check.evidenceReference, name,
                              &check.evidenceShadowMaps);
    out << "evidence: " << dir << " (frame " << check.evidenceFrame << "); open " << dir
        << "/viewer.html to swipe, zoom and probe it\n";
    return kExitConformanceFailure;
  });
}

}  // namespace app
