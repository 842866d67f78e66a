// `lightcts`: parses the command line (SPEC 8) and calls app/commands.h.
// No logic lives here that a test could not reach through the commands.
#include "app/commands.h"
#include "app/exit_status.h"
#include "backends/backend_combinations.h"
#include "backends/gl/gl_context.h"
#include "lighting/light_clusters.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string_view>

int main(int argc, char** argv) {
  // Started by `bench` only; its arguments belong to Google Benchmark, so
  // they bypass the parser below.
  if (argc >= 2 && std::string_view(argv[1]) == "bench-worker") return app::runBenchWorker(argc, argv);

  CLI::App cli{"lightcts: conformance and benchmark suite for one real-time lighting model"};
  cli.require_subcommand(1);
  cli.set_help_all_flag("--help-all", "Show every subcommand's options");

  app::SceneArguments scene;
  app::BackendArguments backend;
  std::string out;
  bool ideal = false;
  bool toleranceTerms = false;
  runner::RunOptions run;
  std::string workerPlan;
  int workerStart = 0;

  auto addScene = [&](CLI::App* sub, bool withFrame) {
    sub->add_option("--scene", scene.scenePath, "Scene file (SPEC 2)")->required();
    if (withFrame) sub->add_option("--frame", scene.frame, "Frame of an animated scene, from 0")->default_val(0);
  };
  // Any Gallium driver's name (docs/cli.md); anything else is a usage error.
  const CLI::Validator mesaDriverName(
      [](std::string& name) {
        return backends::gl::validMesaDriverName(name) ? std::string() : "not a Mesa driver name: [a-z0-9_]+";
      },
      "DRIVER");
  auto addBackend = [&](CLI::App* sub) {
    sub->add_option("--backend", backend.backend, "vulkan | gl-egl | gl-osmesa")->required();
    sub->add_option("--device", backend.device, "Device index or name substring");
    sub->add_option("--driver", backend.driver, "GL backends: a Mesa Gallium driver (llvmpipe, softpipe, zink, ...); vulkan: swiftshader")
        ->check(mesaDriverName);
    // Test-only (docs/cli.md): never needed to run the suite as shipped.
    sub->add_option("--mutant", backend.mutant, "Test only: a deliberately wrong variant of the model")
        ->default_val("none");
    sub->add_option("--admissible", backend.admissible,
                    "Test only: a deliberately different but legal implementation (an admissible variant)")
        ->default_val("none");
    sub->add_flag("--full-shader", backend.fullShader, "Test only: every shader feature on, whatever the scene uses");
    sub->add_option("--expect-driver", backend.expectDriver,
                    "Fail (exit 4) unless the loaded device's name, driver or version contains this text");
    // Benchmark modes beside the model's (docs/cli.md); never the default.
    sub->add_option("--mode", backend.mode,
                    "model (SPEC's light loops, the default) | clustered (Forward+: each pixel loops over its "
                    "screen tile's and depth slice's lights; srp forward scenes without per-object lists)")
        ->capture_default_str()
        ->check(CLI::IsMember({std::string(app::kModelModeName), std::string(lighting::kClusteredModeName)}));
    sub->add_option("--cluster-tile", backend.clusterGrid.tileSize, "--mode clustered: tile side in pixels")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    sub->add_option("--cluster-slices", backend.clusterGrid.depthSlices, "--mode clustered: depth slices")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
  };

  auto* backendsCmd = cli.add_subcommand("backends", "List backends, drivers and devices");
  std::string backendsDriver;
  backendsCmd->add_option("--driver", backendsDriver, "Probe only this driver: a Mesa driver on the GL backends, swiftshader on vulkan")
      ->check(mesaDriverName);
  // Started by `backends` only: one GL driver's probe (backends/gl/probe_in_child.h).
  auto* probeDriverCmd = cli.add_subcommand("probe-driver", "");
  probeDriverCmd->group("");
  std::string probeBackend, probeDriver;
  probeDriverCmd->add_option("--backend", probeBackend)->required();
  probeDriverCmd->add_option("--driver", probeDriver)->required();
  auto* lightsCmd = cli.add_subcommand("lights", "Print the light selection as JSON (SPEC 5.4)");
  addScene(lightsCmd, true);
  bool sceneJson = false;
  lightsCmd->add_flag("--scene-json", sceneJson,
                      "For a glTF file: print instead a scene file that draws it the same way (its camera, image and "
                      "lights, the default rig where it has none) to copy and edit");
  auto* referenceCmd = cli.add_subcommand("reference", "Write reference, tolerance and mask images (EXR)");
  addScene(referenceCmd, true);
  referenceCmd->add_flag("--ideal", ideal, "No budgets: every non-baked light per pixel (SPEC 6)");
  referenceCmd->add_flag("--tolerance-terms", toleranceTerms,
                         "Also write tolerance-arithmetic.exr and tolerance-shift.exr, the two parts of tolerance.exr");
  referenceCmd->add_option("--out", out, "Output folder")->required();
  auto* budgetCmd = cli.add_subcommand("budget", "Where the light budgets bite: reach, kept and loss maps (SPEC 5.5)");
  addScene(budgetCmd, true);
  bool allFrames = false;
  budgetCmd->add_flag("--all-frames", allFrames, "Every frame of an animated scene, with the popping score");
  budgetCmd->add_option("--out", out, "Output folder")->required();
  auto* renderCmd = cli.add_subcommand("render", "Render a scene on a backend to an RGBA float EXR");
  addScene(renderCmd, true);
  addBackend(renderCmd);
  renderCmd->add_option("--out", out, "Output EXR file")->required();
  auto* compareCmd = cli.add_subcommand("compare", "Render and compare against the reference: verdict and metrics");
  addScene(compareCmd, true);
  addBackend(compareCmd);
  std::string evidenceDir;
  compareCmd->add_option("--evidence", evidenceDir,
                         "Folder for the evidence of a failure (default: lightcts-evidence/<group>.<name>.<backend>)");
  bool noEvidence = false;
  compareCmd->add_flag("--no-evidence", noEvidence, "Write no evidence of a failure: the verdict and numbers only")
      ->excludes(compareCmd->get_option("--evidence"));
  auto* runCmd = cli.add_subcommand("run", "Run the whole suite: results.json, junit.xml, report/index.html");
  runCmd->add_option("--backend", run.backends,
                     "Backends to run: an API backend (each of its drivers) or one combination: " +
                         backends::combinationSuffixList() + " (default: every one present)");
  runCmd->add_option("--scenes", run.scenesDir, "Scene folder: <group>/<name>.json, or one group's folder")
      ->default_val("suite/scenes");
  // Not ->required(): CLI11 would demand it of `run compare` too; checked below.
  runCmd->add_option("--out", run.outDir, "Output folder (required)");
  runCmd->add_option("--device", run.device, "Device index or name substring, for every backend");
  runCmd->add_option("--expect-driver", run.expectDriver,
                     "Every backend's device name, driver or version must contain this text (docs/vendors.md)");
  runCmd->add_option("--expected-failures", run.expectedFailureFiles,
                     "Baseline of known failures, 'test,Status  # reason' lines (docs/vendors.md)");
  runCmd->add_option("--timeout", run.timeoutSeconds, "Seconds one test may take before it is a Timeout")
      ->default_val(120);
  runCmd->add_option("--flake-retries", run.flakeRetries,
                     "Re-runs, in a fresh worker, of a test that failed, crashed or timed out (0: none)")
      ->default_val(1)
      ->check(CLI::NonNegativeNumber);
  runCmd->add_flag("--flakes-fail", run.flakesFail, "A Flake (failed, then passed on a retry) fails the run");
  runCmd->add_option("--driver", run.driver,
                     "Run the GL combinations on this Mesa Gallium driver (llvmpipe, softpipe, zink, ...), "
                     "or the Vulkan one on swiftshader")
      ->check(mesaDriverName);
  // Selection by name (SPEC 8): decided before sharding and before any worker starts.
  runCmd->add_option("--include", run.includes,
                     "Run only tests whose <group>.<name>.<backend> matches this shell glob (repeatable)");
  runCmd->add_option("--exclude", run.excludes, "Leave out tests matching this shell glob (repeatable)");
  runCmd->add_option("--caselist", run.caselists, "A file of test names or globs, one a line, '#' comments");
  runCmd->add_flag("--list", run.listOnly, "Print the selected tests (with --shard, the shard's) and run nothing");
  runCmd->add_option("--mutant", run.mutants, "Run only these mutants (default: every one)");
  runCmd->add_flag("--no-mutants", run.noMutants, "Skip the mutation check");
  runCmd->add_flag("--no-budgets", run.noBudgets, "Leave out the light budgets of each scene (SPEC 5.5) from the report");
  runCmd->add_flag("--mutants-only", run.mutantsOnly, "Only the mutation check: exit 0 when every mutant is killed");
  runCmd->add_flag("--mutants-all-scenes", run.mutantsAllScenes,
                   "Check each mutant against every selected scene (the whole kill table), not only its killers");
  // Admissible variants (SPEC 7): legal implementations that must pass every scene.
  runCmd->add_option("--admissible", run.admissible,
                     "Also run every selected scene under these admissible variants (repeatable; 'all' for every "
                     "one): tests <group>.<name>@<variant>.<backend> that must pass");
  runCmd->add_flag("--admissible-only", run.admissibleOnly,
                   "Only the admissible variants' tests: exit 0 when every variant is sound");
  runCmd->add_flag("--admissible-witnesses", run.admissibleWitnesses,
                   "Check each admissible variant against its witnesses (suite/admissible_witnesses.def) alone, "
                   "not every selected scene");
  runCmd->add_flag("--sharpness", run.measureSharpness,
                   "Bisect, for each scene, the smallest relative brightness error its comparison catches "
                   "(results.json metrics)");
  runCmd->add_option("--evidence-limit", run.evidenceLimit,
                     "Failures that keep their evidence images; every failure keeps its numbers")
      ->default_val(50)
      ->check(CLI::NonNegativeNumber);
  runCmd->add_option("--evidence-url", run.evidenceUrl,
                     "junit.xml links each failure's evidence page to this URL, {test} replaced by its name "
                     "(default: the page's path in the run folder)");
  // Parallel workers and shards (docs/ci.md): the cores of one machine, the machines of a CI job.
  runCmd->add_option("--jobs,-j", run.jobs, "Worker processes at once (default: one per core)")
      ->check(CLI::PositiveNumber);
  runCmd->add_option("--tests-per-worker", run.testsPerWorker,
                     "The model's tests a worker process runs before a fresh one takes over; mutants and admissible "
                     "variants go whole into parts of up to as many tasks (fewer starts of the driver and its shader "
                     "compiler against more parts to spread over --jobs)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  std::string shardText;
  runCmd->add_option("--shard", shardText, "Run shard I of N (I from 1): a disjoint part of the run, for CI jobs");
  runCmd->add_option("--timings", run.timingsFile, "An earlier results.json: balance the shards by its test times");
  runCmd->add_flag("--fresh-references", run.freshReferences,
                   "Compute every reference in this run (once, shared by its workers), not from the shared cache");
  // `lightcts merge DIR... --out DIR` (docs/ci.md).
  runner::MergeOptions merge;
  auto* mergeCmd = cli.add_subcommand("merge", "Merge the shards of one run into one results.json and report");
  mergeCmd->add_option("dirs", merge.shardDirs, "The shards' --out folders")->required();
  mergeCmd->add_option("--out", merge.outDir, "Output folder for the merged run")->required();
  mergeCmd->add_option("--evidence-url", merge.evidenceUrl,
                       "junit.xml links each failure's evidence page to this URL, {test} replaced by its name");
  // `lightcts run compare OLD NEW [--out DIR]` (docs/cli.md).
  std::vector<std::string> runCompareFiles;
  std::string runCompareOut;
  auto* runCompareCmd = runCmd->add_subcommand(
      "compare", "Compare two runs: regressions, fixes, new and removed tests, tightness beyond 2x");
  runCompareCmd->add_option("files", runCompareFiles, "OLD/results.json NEW/results.json")->required()->expected(2);
  runCompareCmd->add_option("--out", runCompareOut, "Folder for the comparison page, index.html");
  app::BakeArguments bake;
  auto* bakeCmd = cli.add_subcommand("bake", "Bake lightmaps and shadow masks; write them with overlap maps and bake.json");
  bakeCmd->add_option("--scene", bake.scenePath, "Scene file (SPEC 2)")->required();
  bakeCmd->add_option("--out", bake.outDir, "Output folder")->required();
  bakeCmd->add_flag("--no-cache", bake.noCache, "Bake even when the bake cache holds this bake, and do not store it");
  runner::BenchOptions bench;
  std::vector<std::string> compareFiles;
  auto* benchCmd = cli.add_subcommand("bench", "Benchmarks: speed against error per backend, cost curves");
  benchCmd->add_option("--backend", bench.backends, "Backends or combinations, as for run (default: every one)");
  benchCmd->add_option("--out", bench.outDir, "Output folder: bench.json, index.html, <backend>.html");
  benchCmd->add_option("--scenes", bench.scenesDir, "Scene folder")->default_val("suite/scenes");
  benchCmd->add_flag("--quick", bench.quick, "Fewer points and repetitions (a smoke test, not a measurement)");
  benchCmd->add_flag("--full-set", bench.fullSet,
                     "The full set on every combination, also on a driver whose measured speed would give it the "
                     "scaled-down set (a 1280x720 field frame over a second)");
  benchCmd->add_option("--timeout", bench.timeoutSeconds, "Seconds one benchmark process may take")->default_val(900);
  bool freshErrors = false;
  benchCmd->add_flag("--fresh-errors", freshErrors,
                     "Compute every error in this run, not from the errors kept by earlier runs");
  auto* benchCompareCmd = benchCmd->add_subcommand("compare", "Compare two bench.json files with a U-test");
  benchCompareCmd->add_option("files", compareFiles, "BEFORE.json AFTER.json")->required()->expected(2);

  // Started by `run` only: one backend combination's tests, results as JSON lines.
  auto* workerCmd = cli.add_subcommand("worker", "");
  workerCmd->group("");
  workerCmd->add_option("--plan", workerPlan)->required();
  workerCmd->add_option("--start", workerStart)->default_val(0);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    cli.exit(e);  // prints the message
    return app::kExitBadInput;
  }

  auto& o = std::cout;
  auto& e = std::cerr;
  if (*backendsCmd) return app::runBackendsCommand(backendsDriver, o, e);
  if (*probeDriverCmd) return app::runProbeDriverCommand(probeBackend, probeDriver, o, e);
  if (*lightsCmd) return app::runLightsCommand(scene, sceneJson, o, e);
  if (*referenceCmd) return app::runReferenceCommand(scene, ideal, toleranceTerms, out, o, e);
  if (*budgetCmd) {
    scene.frameGiven = budgetCmd->get_option("--frame")->count() > 0;
    return app::runBudgetCommand(scene, allFrames, out, o, e);
  }
  if (*renderCmd) return app::runRenderCommand(scene, backend, out, o, e);
  scene.frameGiven = compareCmd->get_option("--frame")->count() > 0;
  if (*compareCmd) return app::runCompareCommand(scene, backend, evidenceDir, !noEvidence, o, e);
  if (*bakeCmd) return app::runBakeCommand(bake, o, e);
  if (*runCompareCmd) {
    for (const CLI::Option* option : runCmd->get_options())
      if (option->count() > 0) {
        e << "lightcts: run compare: " << option->get_name() << " is an option of run, not of run compare\n";
        return app::kExitBadInput;
      }
    return app::runRunCompareCommand(runCompareFiles[0], runCompareFiles[1], runCompareOut, o, e);
  }
  if (*runCmd && run.outDir.empty() && !run.listOnly) {
    e << "lightcts: run: --out is required\n";
    return app::kExitBadInput;
  }
  if (*mergeCmd) {
    for (int i = 0; i < argc; ++i) merge.commandLine += (i ? " " : "") + std::string(argv[i]);
    return app::runMergeCommand(merge, o, e);
  }
  if (*runCmd) {
    run.workerExecutable = "/proc/self/exe";
    run.progressInPlace = app::stdoutIsTerminal();
    run.referenceCache = app::referenceCacheDirectory();
    if (!shardText.empty() && !app::parseShardArgument(shardText, run, e)) return app::kExitBadInput;
    for (int i = 0; i < argc; ++i) run.commandLine += (i ? " " : "") + std::string(argv[i]);
    return app::runSuiteCommand(run, o, e);
  }
  if (*benchCompareCmd) return app::runBenchCompareCommand(compareFiles[0], compareFiles[1], o, e);
  if (*benchCmd) {
    if (bench.outDir.empty()) {
      e << "lightcts: bench: --out is required\n";
      return app::kExitBadInput;
    }
    if (!freshErrors) bench.errorCache = app::benchErrorCacheDirectory();
    bench.workerExecutable = "/proc/self/exe";
    for (int i = 0; i < argc; ++i) bench.commandLine += (i ? " " : "") + std::string(argv[i]);
    return app::runBenchCommand(bench, o, e);
  }
  if (*workerCmd) return app::runWorkerCommand(workerPlan, workerStart, o, e);
  return app::kExitBadInput;
}
