# ctest tests driven by the scene files, through the real `lightcts` command.
# Names follow SPEC 10: <group>.<name>.<what>; labels per group and per kind.

# backend_combinations: "<test-name suffix>=<backend>=<driver>", every backend
# and Mesa driver pair of SPEC 10's names, from the one table in backends/.
include(${PROJECT_SOURCE_DIR}/backends/backend_combinations.cmake)
set(backend_test_environment
  "LIGHTCTS_VALIDATION=1"
  "LIGHTCTS_CACHE_DIR=${CMAKE_BINARY_DIR}/cache")

# Under AddressSanitizer (the debug preset), LeakSanitizer reports what the
# driver and the validation layer never free: measured 112 bytes in 2
# allocations from lavapipe and 3.8 KB from VK_LAYER_KHRONOS_validation per
# process. The loader unloads both before LSan runs, so no suppression can name
# them; leak checking stays on for every test that loads no driver.
if(CMAKE_CXX_FLAGS MATCHES "sanitize=address")
  list(APPEND backend_test_environment "ASAN_OPTIONS=detect_leaks=0")
endif()

# Splits "suffix=backend=driver" into suffix, backend and driver_args.
macro(split_combination combination)
  string(REPLACE "=" ";" combination_parts ${combination})
  list(GET combination_parts 0 suffix)
  list(GET combination_parts 1 backend)
  list(GET combination_parts 2 driver)
  set(driver_args)
  if(NOT driver STREQUAL "default")
    set(driver_args --driver ${driver})
  endif()
endmacro()

# The known failures of the drivers CI runs (suite/expected-failures/, the
# file `lightcts run` reads too, scripts/run.sh): a listed test passes only
# when its scene fails the comparison ("Fail <test>:", the expected mismatch),
# so one that starts to pass (a fixed driver: UnexpectedPass) or crashes
# fails. Only the Fail status is listed there.
# Each file names its driver's tests by suffix (mesa-22.3.txt the Mesa
# combinations, swiftshader-5.0.txt vulkan-swiftshader), so all are read.
file(GLOB expected_failures_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/expected-failures/*.txt)
set(expected_failing_tests)
foreach(expected_failures_file ${expected_failures_files})
  file(STRINGS ${expected_failures_file} expected_failure_lines REGEX "^[^#].*,Fail")
  foreach(line ${expected_failure_lines})
    string(REGEX REPLACE ",.*" "" expected_test "${line}")
    list(APPEND expected_failing_tests ${expected_test})
  endforeach()
endforeach()

file(GLOB scene_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/scenes/*/*.json)
list(SORT scene_files)
set(reference_command_groups)
foreach(scene ${scene_files})
  get_filename_component(name ${scene} NAME_WLE)
  get_filename_component(group_dir ${scene} DIRECTORY)
  get_filename_component(group ${group_dir} NAME)
  # The selection of every scene prints (SPEC 5.4).
  add_test(NAME ${group}.${name}.lights
           COMMAND lightcts lights --scene ${scene})
  set_tests_properties(${group}.${name}.lights PROPERTIES LABELS "lights;${group}")
  # `lightcts reference` renders and writes its images (SPEC 8), for the
  # first scene of each group (in name order). Every scene's reference is
  # rendered by its comparisons below, the same renderer at the device's
  # bits; what the command adds, writing the images, is the same code for
  # every scene, and each process that writes images pays about 0.4 s to load
  # OpenImageIO (imaging/image_codec_loader.h): once per group, not per scene.
  if(NOT group IN_LIST reference_command_groups)
    list(APPEND reference_command_groups ${group})
    add_test(NAME ${group}.${name}.reference
             COMMAND lightcts reference --scene ${scene} --out ${CMAKE_BINARY_DIR}/test-out/reference/${group}/${name})
    # It reads and fills the build's reference cache, as the 4-bit devices' comparisons do.
    set_tests_properties(${group}.${name}.reference PROPERTIES LABELS "reference;${group}"
      ENVIRONMENT "LIGHTCTS_CACHE_DIR=${CMAKE_BINARY_DIR}/cache")
  endif()
  # The scene on each combination against the reference (SPEC 7): the
  # verdict of the combination's run below (a test the expected-failures
  # files list must still Fail: the known mismatch detected).
  foreach(combination ${backend_combinations})
    split_combination(${combination})
    set(test ${group}.${name}.${suffix})
    set(want Pass)
    set(labels "${suffix};${group}")
    if(test IN_LIST expected_failing_tests)
      set(want Fail)
      set(labels "${suffix};${group};expected-fail")
    endif()
    add_test(NAME ${test} COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scene_verdict.sh
                                  ${CMAKE_BINARY_DIR}/test-out/scene-runs/${suffix}/verdicts ${test} ${want})
    set_tests_properties(${test} PROPERTIES LABELS "${labels}" SKIP_RETURN_CODE 77
      FIXTURES_REQUIRED scene-run-${suffix})
  endforeach()
endforeach()

# Each combination draws every suite scene in one `lightcts run` in one
# worker process (suite/scene_run.cmake), so a driver start and a shader
# compile per pipeline once, not per scene (SwiftShader compiles a pipeline
# at its first draw in every process, and every GL process loads Mesa and
# LLVM); the scene tests above read its verdicts.
# Vulkan validation is on, and a layer message fails the test it came in
# (the worker reports it as a Crash). Label `scene-runs`.
foreach(combination ${backend_combinations})
  split_combination(${combination})
  add_test(NAME scene-runs.${suffix}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DPYTHON=${LIGHTCTS_PYTHON3}
                   -DSCENES=${CMAKE_CURRENT_SOURCE_DIR}/scenes -DCOMBINATION=${suffix} -DBACKEND=${backend} -DDRIVER=${driver}
                   -DOUT=${CMAKE_BINARY_DIR}/test-out/scene-runs/${suffix} -P ${CMAKE_CURRENT_SOURCE_DIR}/scene_run.cmake)
  # COST: started first (CMakeLists.txt says why); a hung driver is the
  # run's Timeout (120 s a test), not a stalled CI run.
  set_tests_properties(scene-runs.${suffix} PROPERTIES LABELS "scene-runs;${suffix}" FIXTURES_SETUP scene-run-${suffix}
    ENVIRONMENT "${backend_test_environment}" TIMEOUT 1500 COST 60)
endforeach()
# A reference is computed by the first run that needs it and read from the
# cache by every later one of the same precision; a run that needs one
# another run is computing waits on the cache's lock
# (conformance/reference_cache.h), holding a ctest slot idle. So, as a
# scheduling choice, the runs start after the first of their precision on
# Debian's drivers: lavapipe's (8 sub-pixel bits, as llvmpipe) and softpipe's
# on EGL (4, as SwiftShader and zink), and ctest runs other tests meanwhile.
# DEPENDS orders the runs without requiring the first: any one still runs alone.
set_tests_properties(scene-runs.gl-egl scene-runs.gl-osmesa PROPERTIES DEPENDS scene-runs.vulkan)
set_tests_properties(scene-runs.gl-osmesa-softpipe scene-runs.vulkan-swiftshader scene-runs.gl-egl-zink
                     PROPERTIES DEPENDS scene-runs.gl-egl-softpipe)

# Mutants (SPEC 7): suite/mutant_tests.cmake. `lightcts run` itself:
# suite/run_tests.cmake; choosing its tests by name: suite/test_choice_tests.cmake. Selection checks (SPEC 5.4, written by hand):
# suite/selection_tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/mutant_tests.cmake)
# Admissible variants (SPEC 7): suite/admissible_tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/admissible_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/run_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/parallel_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/test_choice_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/gltf_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/vacuous_tests.cmake)
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/selection_tests.cmake)
  include(${CMAKE_CURRENT_LIST_DIR}/selection_tests.cmake)
endif()

# The command-line contract of SPEC 8 through the real binary: exit statuses
# and messages. (The same paths are unit-tested in app/tests.)
set(bad_scene ${CMAKE_CURRENT_SOURCE_DIR}/bad-scenes/typo-in-range.json)
add_test(NAME cli.typo-in-scene-exits-2
         COMMAND sh -c "$<TARGET_FILE:lightcts> lights --scene ${bad_scene}; test $? -eq 2")
add_test(NAME cli.typo-in-scene-names-the-path
         COMMAND lightcts reference --scene ${bad_scene} --out ${CMAKE_BINARY_DIR}/test-out/bad)
set_tests_properties(cli.typo-in-scene-names-the-path PROPERTIES
  WILL_FAIL FALSE PASS_REGULAR_EXPRESSION "typo-in-range.json:7:[0-9]+: /lights/0/rnage: unknown key")
add_test(NAME cli.unknown-backend-exits-2
         COMMAND sh -c "$<TARGET_FILE:lightcts> compare --scene ${scene} --backend metal; test $? -eq 2")
add_test(NAME cli.unknown-option-exits-2
         COMMAND sh -c "$<TARGET_FILE:lightcts> lights --scene ${scene} --bogus; test $? -eq 2")
# `lightcts budget` (SPEC 5.5): a frame out of range and no scene are bad input.
add_test(NAME cli.budget-frame-out-of-range-exits-2
         COMMAND sh -c "$<TARGET_FILE:lightcts> budget --scene ${scene} --frame 99 --out ${CMAKE_BINARY_DIR}/test-out/budget-bad; test $? -eq 2")
add_test(NAME cli.budget-without-scene-exits-2
         COMMAND sh -c "$<TARGET_FILE:lightcts> budget --out ${CMAKE_BINARY_DIR}/test-out/budget-bad; test $? -eq 2")
set_tests_properties(cli.typo-in-scene-exits-2 cli.typo-in-scene-names-the-path cli.unknown-backend-exits-2
  cli.unknown-option-exits-2 cli.budget-frame-out-of-range-exits-2 cli.budget-without-scene-exits-2
  PROPERTIES LABELS "cli")
