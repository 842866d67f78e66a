#include "app/commands.h"
#include "app/exit_status.h"
#include "app/scene_input.h"
#include "conformance/reference_cache.h"
#include "conformance/scene_check.h"
#include "imaging/image_codec_loader.h"
#include "imaging/image_files.h"
#include "reference/reference_renderer.h"

#include <filesystem>
#include <ostream>

namespace app {

// SPEC 8: DIR/reference.exr (RGB value, A mask), DIR/tolerance.exr (RGB), and
// a tone-mapped sRGB preview DIR/reference.png for people; with
// --tolerance-terms the tolerance's two parts as well (docs/tolerances.md).
int runReferenceCommand(const SceneArguments& args, bool ideal, bool toleranceTerms, const std::string& outDir,
                        std::ostream& out, std::ostream& err) {
  return guardCommand(err, [&] {
    const SceneInput input = loadSceneInput(args);
    imaging::requireImageModule();
    makeOutputDirectory(outDir);
    // The plain reference is the one every 4-bit device's comparison uses
    // (SceneReferences::reference at the minimum bits), so it comes from and
    // goes to the shared reference cache; --ideal and --tolerance-terms are
    // rendered here and kept nowhere.
    reference::ReferenceImages images;
    if (!ideal && !toleranceTerms) {
      conformance::SceneReferences references(
          input.prepared, conformance::referenceCaching(conformance::defaultReferenceCacheDirectory(), args.scenePath,
                                                        input.prepared->scene));
      images = references.reference(args.frame);
    } else {
      reference::ReferenceOptions options;
      options.ideal = ideal;
      options.keepToleranceTerms = toleranceTerms;
      options.bakedLightsRealtime = input.frame.scene().expect.against == lighting::CompareAgainst::Realtime;  // as compare does
      images = reference::ReferenceRenderer(input.prepared).render(input.frame, options);
    }
    const std::filesystem::path dir(outDir);
    imaging::writeExr((dir / "reference.exr").string(), images.value);
    imaging::writeExr((dir / "tolerance.exr").string(), images.tolerance);
    imaging::writePngPreview((dir / "reference.png").string(), images.value);
    if (toleranceTerms) {
      imaging::writeExr((dir / "tolerance-arithmetic.exr").string(), images.toleranceArithmetic);
      imaging::writeExr((dir / "tolerance-shift.exr").string(), images.toleranceShift);
    }
    out << "reference: " << input.frame.scene().name << " frame " << args.frame << (ideal ? " (ideal)" : "") << ": "
        << images.value.width << "x" << images.value.height << ", " << images.maskedPixels
        << " pixel(s) masked, written to " << outDir << "\n";
    return kExitSuccess;
  });
}

}  // namespace app
