# `lightcts run` through the real binary: crashes and hangs of a
# worker are recorded and the run completes, bad input exits 2, a missing
# backend is NotSupported, a baseline turns verdicts, a driver that is not the
# one asked for never passes. Included by scene_tests.cmake.
set(run_scenes ${CMAKE_CURRENT_SOURCE_DIR}/scenes/attenuation)
set(run_out ${CMAKE_BINARY_DIR}/test-out/run)
set(one_test attenuation.point-d-half-range.vulkan)
set(neighbour attenuation.point-d-range.vulkan)

# name | expected exit | run arguments | environment | verdicts | backends | output regex
function(add_run_test name exit_status args env verdicts backends regex)
  add_test(NAME run.${name}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DOUT=${run_out}/${name} -DEXIT=${exit_status}
                   "-DARGS=${args}" "-DENV=${env}" "-DVERDICTS=${verdicts}" "-DBACKENDS=${backends}"
                   "-DOUTPUT_REGEX=${regex}" -P ${CMAKE_CURRENT_SOURCE_DIR}/run_outcome.cmake)
  set_tests_properties(run.${name} PROPERTIES LABELS "run;vulkan" SKIP_REGULAR_EXPRESSION "NotSupported: no backend"
    ENVIRONMENT "${backend_test_environment}")
endfunction()

set(vulkan_only "--backend;vulkan;--scenes;${run_scenes};--no-mutants")
add_run_test(killed-worker-is-crash 1 "${vulkan_only}" "LIGHTCTS_TEST_CRASH_ON=${one_test}"
  "${one_test}=Crash;${neighbour}=Pass" "vulkan=ran" "")
add_run_test(hung-worker-is-timeout 1 "${vulkan_only};--timeout;3" "LIGHTCTS_TEST_HANG_ON=${one_test}"
  "${one_test}=Timeout;${neighbour}=Pass" "vulkan=ran" "")
add_run_test(typo-in-scene-exits-2 2 "--scenes;${CMAKE_CURRENT_SOURCE_DIR}/bad-scenes" "" "" ""
  "typo-in-range.json:7:[0-9]+: /lights/0/rnage: unknown key")
add_run_test(unknown-backend-exits-2 2 "--backend;metal;--scenes;${run_scenes}" "" "" "" "unknown backend 'metal'")
add_run_test(missing-driver-is-not-supported 3 "${vulkan_only}" "VK_ICD_FILENAMES=/nonexistent/icd.json" "" ""
  "no backend asked for is present")
add_run_test(wrong-driver-never-passes 1 "${vulkan_only};--expect-driver;no-such-vendor" "" "${one_test}=Crash"
  "vulkan=error" "does not match the loaded device")
# gl-egl-zink with lavapipe unusable (VK_LOADER_DRIVERS_DISABLE): NotSupported,
# never a pass on another Vulkan driver.
add_run_test(zink-without-lavapipe-is-not-supported 3
  "--backend;gl-egl-zink;--scenes;${run_scenes};--no-mutants" "VK_LOADER_DRIVERS_DISABLE=*lvp*"
  "attenuation.point-d-half-range.gl-egl-zink=NotSupported" "gl-egl-zink=NotSupported" "no backend asked for is present")
set_tests_properties(run.zink-without-lavapipe-is-not-supported PROPERTIES LABELS "run;gl-egl-zink")

# A baseline: the crash listed becomes ExpectedFail, a listed test that passes
# UnexpectedPass.
set(baseline ${CMAKE_CURRENT_BINARY_DIR}/run-baseline.txt)  # the tests' inputs live beside them, not in test-out
file(WRITE ${baseline} "# written by suite/run_tests.cmake\n${one_test},Crash  # crashed on purpose (LIGHTCTS_TEST_CRASH_ON)\n${neighbour},Fail  # listed although it passes\n")
add_run_test(expected-failures-baseline 1 "${vulkan_only};--expected-failures;${baseline}"
  "LIGHTCTS_TEST_CRASH_ON=${one_test}" "${one_test}=ExpectedFail;${neighbour}=UnexpectedPass" "" "")

# deqp-runner's lists: a run with a crash writes failures.csv,
# which loads back as the expected failures of the next run as it is (the
# crash becomes ExpectedFail, the run passes). The junit.xml of both runs
# (an <error>, then a <skipped>) validates against the JUnit schema Jenkins
# uses, with BACKEND.GROUP classnames (reports/tests/check_junit_schema.sh;
# exit 77, a skip, without xmllint).
add_run_test(csv-failures-of-a-crash 1 "${vulkan_only}" "LIGHTCTS_TEST_CRASH_ON=${one_test}"
  "${one_test}=Crash;${neighbour}=Pass" "vulkan=ran" "")
set_tests_properties(run.csv-failures-of-a-crash PROPERTIES FIXTURES_SETUP run-csv-seed)
add_run_test(failures-csv-is-an-expected-failures-file 0
  "${vulkan_only};--expected-failures;${run_out}/csv-failures-of-a-crash/failures.csv"
  "LIGHTCTS_TEST_CRASH_ON=${one_test}" "${one_test}=ExpectedFail;${neighbour}=Pass" "vulkan=ran" "")
set_tests_properties(run.failures-csv-is-an-expected-failures-file PROPERTIES
  FIXTURES_REQUIRED run-csv-seed FIXTURES_SETUP run-csv-baseline)
add_test(NAME run.results-csv-lists-every-test-with-its-verdict
         COMMAND ${PROJECT_SOURCE_DIR}/reports/tests/check_run_csv.sh ${run_out}/csv-failures-of-a-crash
                 ${run_scenes} 1 ${one_test}=Crash ${neighbour}=Pass)
set_tests_properties(run.results-csv-lists-every-test-with-its-verdict PROPERTIES LABELS "run;vulkan"
  FIXTURES_REQUIRED run-csv-seed)
add_test(NAME run.junit-of-real-runs-validates-against-schema
         COMMAND ${PROJECT_SOURCE_DIR}/reports/tests/check_junit_schema.sh
                 ${run_out}/csv-failures-of-a-crash/junit.xml
                 ${run_out}/failures-csv-is-an-expected-failures-file/junit.xml)
set_tests_properties(run.junit-of-real-runs-validates-against-schema PROPERTIES LABELS "run;report;vulkan"
  FIXTURES_REQUIRED "run-csv-seed;run-csv-baseline" SKIP_RETURN_CODE 77)

# A real failure with evidence in junit.xml: the expect_fail scene whose
# mismatch is detected (so it leaves evidence) listed as a known Fail, so it
# passes unexpectedly, a failure; its testcase names its viewer through
# --evidence-url, and the file still validates against the schema.
set(evidence_baseline ${CMAKE_CURRENT_BINARY_DIR}/evidence-baseline.txt)
file(WRITE ${evidence_baseline}
  "baked.legacy-falloff-vs-realtime.vulkan,Fail  # listed so that it passes unexpectedly (suite/run_tests.cmake)\n")
add_run_test(junit-names-the-evidence-page 1
  "--backend;vulkan;--scenes;${CMAKE_CURRENT_SOURCE_DIR}/scenes/baked;--include;baked.legacy-falloff-vs-realtime.*;--no-mutants;--expected-failures;${evidence_baseline};--evidence-url;https://ci.example/run/evidence/{test}/viewer.html"
  "" "baked.legacy-falloff-vs-realtime.vulkan=UnexpectedPass" "vulkan=ran" "")
set_tests_properties(run.junit-names-the-evidence-page PROPERTIES FIXTURES_SETUP run-evidence-junit)
add_test(NAME run.junit-with-evidence-validates-and-names-the-page
         COMMAND ${CMAKE_COMMAND} -DJUNIT=${run_out}/junit-names-the-evidence-page/junit.xml
                 -DCHECK=${PROJECT_SOURCE_DIR}/reports/tests/check_junit_schema.sh
                 "-DPAGE=https://ci.example/run/evidence/baked.legacy-falloff-vs-realtime.vulkan/viewer.html"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/junit_names_evidence.cmake)
set_tests_properties(run.junit-with-evidence-validates-and-names-the-page PROPERTIES LABELS "run;report;vulkan"
  FIXTURES_REQUIRED run-evidence-junit SKIP_RETURN_CODE 77)

# A real run whose report has images (the killing scene of a mutant), opened
# in headless Chromium: every <img> must load (reports/tests/check_images_load.sh;
# exit 77, a skip, when Chromium is not installed).
add_run_test(real-run-report 0 "--backend;vulkan;--scenes;${run_scenes};--mutant;distance-clamp-1e-4" "" ""
  "vulkan=ran" "mutants: 1 killed, 0 survived")
set_tests_properties(run.real-run-report PROPERTIES FIXTURES_SETUP real-run)
# Two mutants packed into one worker part; the first one's backend does not
# build (LIGHTCTS_TEST_BACKEND_ERROR_FOR_MUTANT): the combination is in error
# and that mutant crashed, but the second is still checked, and killed, in a
# fresh worker (runner/part_run.cpp).
add_run_test(broken-mutant-backend-costs-only-its-tasks 1
  "--backend;vulkan;--scenes;${run_scenes};--mutant;distance-clamp-1e-4;--mutant;unsquared-spot"
  "LIGHTCTS_TEST_BACKEND_ERROR_FOR_MUTANT=distance-clamp-1e-4" "${one_test}=Pass" "vulkan=error"
  "mutants: 1 killed, 0 survived")
add_test(NAME run.real-run-report-images-load-in-chromium
         COMMAND ${PROJECT_SOURCE_DIR}/reports/tests/check_images_load.sh ${run_out}/real-run-report)
set_tests_properties(run.real-run-report-images-load-in-chromium PROPERTIES LABELS "run;report;vulkan"
  FIXTURES_REQUIRED real-run SKIP_RETURN_CODE 77)
# The same failing report, as a reader opens it: every evidence viewer it
# links to (the mutant's kill) is driven in headless Chromium over the
# DevTools protocol, with every network access failing; the probe must show
# the EXR files' floats at chosen pixels (read with OpenImageIO's Python
# module), and the page must load nothing from the network
# (reports/tests/viewer_probe_test.py; one browser for both).
add_test(NAME run.real-run-report-viewer-probes-the-exr-values-with-no-network
         COMMAND ${LIGHTCTS_PYTHON3} ${PROJECT_SOURCE_DIR}/reports/tests/viewer_probe_test.py --no-network
                 --report ${run_out}/real-run-report/report/index.html)
set_tests_properties(run.real-run-report-viewer-probes-the-exr-values-with-no-network
  PROPERTIES LABELS "run;report;vulkan" FIXTURES_REQUIRED real-run SKIP_RETURN_CODE 77 TIMEOUT 150)

# `lightcts bench --quick` end to end on Vulkan: bench.json and the
# pages are written, and every plot renders in headless Chromium
# (reports/tests/check_svgs_render.sh; exit 77, a skip, without Chromium).
# A smoke test of the wiring, never a measurement: speed is not asserted.
# --fresh-errors: every run computes its ideals and errors (the errors kept
# across runs have a test of their own, bench.error-cache-smoke).
set(bench_out ${CMAKE_BINARY_DIR}/test-out/bench-quick)
add_test(NAME bench.command-quick
         COMMAND lightcts bench --quick --fresh-errors --backend vulkan --scenes ${CMAKE_CURRENT_SOURCE_DIR}/scenes
                 --out ${bench_out})
set_tests_properties(bench.command-quick PROPERTIES LABELS "bench;vulkan" FIXTURES_SETUP bench-quick
  SKIP_RETURN_CODE 3 TIMEOUT 300 COST 15)  # COST: started first (CMakeLists.txt says why)
add_test(NAME bench.command-quick-plots-render-in-chromium
         COMMAND ${PROJECT_SOURCE_DIR}/reports/tests/check_svgs_render.sh ${bench_out})
set_tests_properties(bench.command-quick-plots-render-in-chromium PROPERTIES LABELS "bench;report"
  FIXTURES_REQUIRED bench-quick SKIP_RETURN_CODE 77)
add_test(NAME bench.compare-against-itself-finds-no-regression
         COMMAND lightcts bench compare ${bench_out}/bench.json ${bench_out}/bench.json)
set_tests_properties(bench.compare-against-itself-finds-no-regression PROPERTIES LABELS "bench"
  FIXTURES_REQUIRED bench-quick)

# Flake detection: LIGHTCTS_TEST_CRASH_ONCE crashes the worker at
# one test only while its marker file is absent (the worker creates it first),
# so the first attempt is a Crash and the retry in a fresh worker passes: the
# test is Flake, listed apart, and the run passes; with --flakes-fail a Flake
# fails the run; with --flake-retries 0 nothing is retried and it is a Crash.
function(add_flake_test name exit_status extra_args verdict regex)
  add_run_test(${name} ${exit_status} "${vulkan_only};${extra_args}"
    "LIGHTCTS_TEST_CRASH_ONCE=${one_test}:${run_out}/${name}/crash-once.marker"
    "${one_test}=${verdict};${neighbour}=Pass" "vulkan=ran" "${regex}")
endfunction()
set(flake_listed "flaky tests [^\n]*\n  ${one_test}: Crash, Pass")
add_flake_test(crash-once-is-flake 0 "" Flake "1 Flake.*${flake_listed}")
add_flake_test(flakes-fail-fails-the-run 1 "--flakes-fail" Flake "${flake_listed}")
add_flake_test(flake-retries-0-keeps-the-crash 1 "--flake-retries;0" Crash "1 Crash")

# `lightcts run compare OLD NEW --out DIR`: a real run against
# itself is no change (exit 0); against a copy of it with one verdict edited
# Pass -> Fail, and against a real run where that test crashed
# (LIGHTCTS_TEST_CRASH_ON), it names the regression (exit 1); the other way
# round it is a fix (exit 0). A missing file or one that is not a results.json
# exits 2 and writes nothing (suite/run_compare_outcome.cmake).
add_run_test(compare-base 0 "${vulkan_only}" "" "${one_test}=Pass;${neighbour}=Pass" "vulkan=ran" "")
add_run_test(compare-crash 1 "${vulkan_only}" "LIGHTCTS_TEST_CRASH_ON=${one_test}" "${one_test}=Crash" "vulkan=ran" "")
set_tests_properties(run.compare-base PROPERTIES FIXTURES_SETUP run-compare-base)
set_tests_properties(run.compare-crash PROPERTIES FIXTURES_SETUP run-compare-crash)
set(compare_base ${run_out}/compare-base/results.json)
set(compare_crash ${run_out}/compare-crash/results.json)
# name | expected exit | OLD | NEW | test=Verdict edit of NEW, or "" | output regex | fixtures
function(add_run_compare_test name exit_status old new edit regex fixtures)
  add_test(NAME run.compare.${name}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DOLD=${old} -DNEW=${new}
                   -DOUT=${run_out}/compare.${name} -DEXIT=${exit_status} "-DEDIT=${edit}" "-DOUTPUT_REGEX=${regex}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/run_compare_outcome.cmake)
  set_tests_properties(run.compare.${name} PROPERTIES LABELS "run;report;vulkan" FIXTURES_REQUIRED "${fixtures}"
    SKIP_REGULAR_EXPRESSION "NotSupported: no backend")
endfunction()
add_run_compare_test(against-itself-is-no-change 0 ${compare_base} ${compare_base} ""
  "no change" run-compare-base)
add_run_compare_test(edited-pass-to-fail-is-a-regression 1 ${compare_base} ${compare_base} "${one_test}=Fail"
  "REGRESSION ${one_test}: Pass -> Fail.1 regression, 0 fixes" run-compare-base)
add_run_compare_test(crashing-run-is-a-regression 1 ${compare_base} ${compare_crash} ""
  "REGRESSION ${one_test}: Pass -> Crash.1 regression," "run-compare-base;run-compare-crash")
add_run_compare_test(crash-to-pass-is-a-fix 0 ${compare_crash} ${compare_base} ""
  "fix ${one_test}: Crash -> Pass.0 regressions, 1 fix," "run-compare-base;run-compare-crash")
add_run_compare_test(missing-file-exits-2 2 ${run_out}/no-such-run/results.json ${compare_base} ""
  "no-such-run/results.json: cannot be read" run-compare-base)
add_run_compare_test(not-a-results-file-exits-2 2 ${CMAKE_CURRENT_SOURCE_DIR}/bad-scenes/typo-in-range.json
  ${compare_base} "" "typo-in-range.json: not a lightcts results.json" run-compare-base)
# `run` has a subcommand now, so its --out is checked by `run` (not the parser):
# still exit 2 without it, and nothing runs.
add_test(NAME run.compare.run-without-out-still-exits-2
         COMMAND sh -c "out=$($<TARGET_FILE:lightcts> run --backend vulkan --scenes '${run_scenes}' --no-mutants 2>&1); \
                        s=$?; echo \"$out\"; test $s -eq 2 && echo \"$out\" | grep -q 'run: --out is required'")
set_tests_properties(run.compare.run-without-out-still-exits-2 PROPERTIES LABELS "run;cli")

# The light budgets in the report (SPEC 5.5): a run of the three scenes the
# budget tests derive by hand (reference/tests/light_budget_test.cpp) shows
# the cutting ones' maps and figures and the legacy one's single line, and
# every image loads in headless Chromium.
add_run_test(budget-report 0
  "--backend;vulkan;--scenes;${CMAKE_CURRENT_SOURCE_DIR}/scenes;--no-mutants;--include;limits.popping-64.*;--include;per-object.eleven-lights.*;--include;legacy.four-pixel-four-vertex.*"
  "" "limits.popping-64.vulkan=Pass;per-object.eleven-lights.vulkan=Pass;legacy.four-pixel-four-vertex.vulkan=Pass"
  "vulkan=ran" "light budgets of 3 scene")
set_tests_properties(run.budget-report PROPERTIES FIXTURES_SETUP budget-run)
add_test(NAME run.budget-report-shows-maps-in-chromium
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_budget_report.sh ${run_out}/budget-report)
set_tests_properties(run.budget-report-shows-maps-in-chromium PROPERTIES LABELS "run;report;vulkan;budget"
  FIXTURES_REQUIRED budget-run SKIP_RETURN_CODE 77)
