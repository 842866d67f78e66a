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
foreach(scene ${scene_files})
  get_filename_component(name ${scene} NAME_WLE)
  get_filename_component(group_dir ${scene} DIRECTORY)
  get_filename_component(group ${group_dir} NAME)
  # The selection of every scene prints (SPEC 5.4).
  add_test(NAME ${group}.${name}.lights
           COMMAND lightcts lights --scene ${scene})
  set_tests_properties(${group}.${name}.lights PROPERTIES LABELS "lights;${group}")
  # The reference renders and writes its images (SPEC 8).
  add_test(NAME ${group}.${name}.reference
           COMMAND lightcts reference --scene ${scene} --out ${CMAKE_BINARY_DIR}/test-out/reference/${group}/${name})
  # It reads and fills the build's reference cache, as the 4-bit devices' comparisons do.
  set_tests_properties(${group}.${name}.reference PROPERTIES LABELS "reference;${group}"
    ENVIRONMENT "LIGHTCTS_CACHE_DIR=${CMAKE_BINARY_DIR}/cache")
  # The scene on each backend against the reference (SPEC 7): exit 3 (no
  # device or driver) is a skip; Vulkan validation is on and any layer
  # message fails.
  foreach(combination ${backend_combinations})
    split_combination(${combination})
    set(test ${group}.${name}.${suffix})
    add_test(NAME ${test}
             COMMAND lightcts compare --scene ${scene} --backend ${backend} ${driver_args}
                     --evidence ${CMAKE_BINARY_DIR}/test-out/evidence/${test})
    # A hung driver is a Timeout, not a stalled CI run.
    set_tests_properties(${test} PROPERTIES LABELS "${suffix};${group}" SKIP_RETURN_CODE 3 TIMEOUT 300
      ENVIRONMENT "${backend_test_environment}" FAIL_REGULAR_EXPRESSION "Validation (Error|Warning)|VUID-")
    if(test IN_LIST expected_failing_tests)
      string(REPLACE "." "\\." test_pattern ${test})
      set_tests_properties(${test} PROPERTIES PASS_REGULAR_EXPRESSION "(^|\n)Fail ${test_pattern}:"
        LABELS "${suffix};${group};expected-fail")
    endif()
  endforeach()
endforeach()

# Mutants (SPEC 7): suite/mutant_tests.cmake. `lightcts run` itself:
# suite/run_tests.cmake; choosing its tests by name: suite/test_choice_tests.cmake. Selection checks (SPEC 5.4, written by hand):
# suite/selection_tests.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/mutant_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/run_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/parallel_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/test_choice_tests.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/gltf_tests.cmake)
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
