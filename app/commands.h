// The `lightcts` subcommands (SPEC 8). main.cpp only parses arguments and calls
// these; each returns an exit status (exit_status.h) and reports errors on
// `err` with a message a user can act on.
#pragma once

#include "lighting/light_clusters.h"
#include "runner/bench_run.h"
#include "runner/run_merge.h"
#include "runner/suite_run.h"

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace app {

// --mode's default: SPEC's own light loops.
inline constexpr const char* kModelModeName = "model";

struct SceneArguments {
  std::string scenePath;
  int frame = 0;
  bool frameGiven = false;  // compare: false checks every frame of an animated scene
};

int runBackendsCommand(std::ostream& out, std::ostream& err);
// `lightcts backends --driver NAME`: only that Mesa driver, on each GL
// backend; exit 3 when it comes up on none (docs/cli.md).
int runBackendsCommand(const std::string& driver, std::ostream& out, std::ostream& err);
// The hidden `lightcts probe-driver` that `backends` starts per GL driver
// (backends/gl/probe_in_child.h).
int runProbeDriverCommand(const std::string& backend, const std::string& driver, std::ostream& out,
                          std::ostream& err);
// `sceneJson` (extension, docs/cli.md): for a glTF file, the scene file that
// draws it (scene_input/gltf_scene_json.h) instead of the selection.
int runLightsCommand(const SceneArguments& args, bool sceneJson, std::ostream& out, std::ostream& err);
// `toleranceTerms` (extension, docs/cli.md): also DIR/tolerance-arithmetic.exr
// and DIR/tolerance-shift.exr, the two parts of tolerance.exr.
int runReferenceCommand(const SceneArguments& args, bool ideal, bool toleranceTerms, const std::string& outDir,
                        std::ostream& out, std::ostream& err);

// SPEC 5.5: DIR/budget.json, reach.png, kept.png, loss.exr, loss.png for the
// frame; with `allFrames`, or for an animated scene without --frame, each
// frame in DIR/frame-<f>/, the popping score beside each and
// DIR/kept-strip.png (docs/cli.md).
int runBudgetCommand(const SceneArguments& args, bool allFrames, const std::string& outDir, std::ostream& out,
                     std::ostream& err);

struct BackendArguments {
  std::string backend{};
  std::string device{};
  std::string driver{};
  // Test-only extensions of SPEC 8 (docs/cli.md): a deliberately wrong
  // variant of the model (shaders/shader_variant.h), or every shader feature
  // on whatever the scene uses.
  std::string mutant = "none";
  // --admissible: a deliberately different but legal implementation
  // (SPEC 7's admissible variants, shaders/shader_interface.def).
  std::string admissible = "none";
  bool fullShader = false;
  // --expect-driver (docs/vendors.md): the loaded device's name, driver or
  // driver version must contain this text, or the command fails (exit 4).
  std::string expectDriver{};
  // --mode (extension, docs/cli.md): kModelModeName, the model as SPEC
  // specifies it (the default), or lighting::kClusteredModeName, the Forward+
  // benchmark mode (lighting/light_clusters.h) with this grid
  // (--cluster-tile pixels a tile side, --cluster-slices depth slices).
  std::string mode = kModelModeName;
  lighting::ClusterGridSpec clusterGrid{};
};
int runRenderCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& outFile,
                     std::ostream& out, std::ostream& err);
// Evidence of a failure goes to `evidenceDir`, or when empty to
// lightcts-evidence/<group>.<name>.<backend> under the current folder;
// nowhere with writeEvidence false (--no-evidence: the verdict and numbers only).
int runCompareCommand(const SceneArguments& args, const BackendArguments& backend, const std::string& evidenceDir,
                      bool writeEvidence, std::ostream& out, std::ostream& err);
// `run` checks its options (unknown backend or mutant, bad scene: exit 2)
// before any worker starts.
int runSuiteCommand(const runner::RunOptions& options, std::ostream& out, std::ostream& err);
// `lightcts run compare OLD NEW [--out DIR]`: regressions, fixes,
// new and removed tests, tightness beyond 2x; DIR/index.html when `outDir` is
// not empty. 0 no regression, 1 a regression, 2 a file missing, unreadable or
// not a lightcts results.json (nothing written).
int runRunCompareCommand(const std::string& oldFile, const std::string& newFile, const std::string& outDir,
                         std::ostream& out, std::ostream& err);
// `lightcts bench` (docs/bench-format.md) and `lightcts bench compare BEFORE AFTER`.
int runBenchCommand(const runner::BenchOptions& options, std::ostream& out, std::ostream& err);
int runBenchCompareCommand(const std::string& before, const std::string& after, std::ostream& out,
                           std::ostream& err);
// The hidden `lightcts bench-worker KIND ...` that `bench` starts: argv as
// main received it (KIND is argv[2]); the rest goes to Google Benchmark.
int runBenchWorker(int argc, char** argv);
// `lightcts bake --scene S --out DIR [--no-cache]` (docs/cli.md, docs/baking.md):
// the lightmaps, shadow masks and channel-overlap maps of every lightmapped
// object, and DIR/bake.json. A scene without a lightmapped object exits 2.
struct BakeArguments {
  std::string scenePath;
  std::string outDir;
  bool noCache = false;  // bake even when the cache holds this bake, and do not store it
};
int runBakeCommand(const BakeArguments& args, std::ostream& out, std::ostream& err);
// `lightcts merge DIR... --out DIR` (runner/run_merge.h): 0 the merged run
// passes, 1 it has a failure, 2 the folders are not the shards of one run
// (the reason on stderr, nothing written).
int runMergeCommand(const runner::MergeOptions& options, std::ostream& out, std::ostream& err);
// For `run`: whether stdout is a terminal (progress redrawn in place), the
// reference cache folder (conformance/reference_cache.h; "" when none is
// known), and --shard I/N into options.shard (false, with the message on
// `err`, when it is not I/N with 1 <= I <= N).
bool stdoutIsTerminal();
std::string referenceCacheDirectory();
// Where `bench` keeps its errors across runs; "" when no cache folder is known.
std::string benchErrorCacheDirectory();
bool parseShardArgument(const std::string& text, runner::RunOptions& options, std::ostream& err);
// The hidden `lightcts worker` command that `run` starts (runner/suite_worker.h).
int runWorkerCommand(const std::string& planFile, int start, std::ostream& out, std::ostream& err);

}  // namespace app
