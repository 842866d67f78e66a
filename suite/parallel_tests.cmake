# `lightcts run --jobs`, `--shard` and `lightcts merge` through the
# real binary and real drivers (suite/parallel_outcome.cmake). Included by
# scene_tests.cmake, which defines backend_test_environment.
set(parallel_out ${CMAKE_BINARY_DIR}/test-out/parallel)
set(parallel_scenes ${CMAKE_CURRENT_SOURCE_DIR}/scenes/attenuation)
set(parallel_crash attenuation.point-d-half-range.vulkan)

# name | mode | run arguments | environment
function(add_parallel_test name mode args env)
  add_test(NAME run.${name}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DPYTHON=${LIGHTCTS_PYTHON3}
                   -DCHECK=${CMAKE_CURRENT_SOURCE_DIR}/check_same_results.py -DOUT=${parallel_out}/${name}
                   -DMODE=${mode} "-DARGS=${args}" "-DENV=${env}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/parallel_outcome.cmake)
  set_tests_properties(run.${name} PROPERTIES LABELS "run;vulkan" SKIP_REGULAR_EXPRESSION "NotSupported: no backend"
    ENVIRONMENT "${backend_test_environment}" COST 30)
endfunction()

# Two combinations (vulkan, and gl-egl on llvmpipe), so parts of both run at
# once; two mutants with their killers, so the mutation check's parts and
# kill table are compared too; a worker that crashes (LIGHTCTS_TEST_CRASH_ON),
# so crash isolation is checked with two workers at once (the run exits 1 for
# it). Five scenes of the group, so each of 3 shards holds several tests of
# both combinations; a test runs up to 7 times, so more scenes only cost time.
set(parallel_selection
  "--include;attenuation.point-5mm-above-floor.*;--include;attenuation.point-3mm-above-floor-close-up.*"
  "--include;attenuation.spot-inner-outer-edges.*;--include;attenuation.point-d-half-range.*"
  "--include;attenuation.directional-grazing.*")
set(parallel_args "--backend;vulkan;--backend;gl-egl;--driver;llvmpipe;--scenes;${parallel_scenes};${parallel_selection};--mutant;distance-clamp-1e-4;--mutant;unsquared-spot;--flake-retries;0")
add_parallel_test(jobs-1-and-2-write-the-same jobs "${parallel_args}" "LIGHTCTS_TEST_CRASH_ON=${parallel_crash}")
add_parallel_test(shards-merge-into-the-whole-run shards "${parallel_args}" "")
# The shards of a selection (an --exclude among the --include) merge into the
# selection: the same as one run of it. What else a merge checks is the test above's.
add_parallel_test(shards-of-a-selection-merge-into-the-selection selection-shards
  "--backend;vulkan;--scenes;${parallel_scenes};--include;attenuation.*;--exclude;*-range.vulkan;--mutant;distance-clamp-1e-4;--flake-retries;0"
  "")
