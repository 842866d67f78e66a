# ctest tests driven by the scene files, through the real `lightcts` command.
# Names follow SPEC 10: <group>.<name>.<what>; labels per group and per kind.
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
  set_tests_properties(${group}.${name}.reference PROPERTIES LABELS "reference;${group}")
  # The scene on each backend against the reference (SPEC 7): exit 3 (no
  # device) is a skip; validation is on and any layer message fails.
  add_test(NAME ${group}.${name}.vulkan
           COMMAND lightcts compare --scene ${scene} --backend vulkan
                   --evidence ${CMAKE_BINARY_DIR}/test-out/evidence/${group}.${name}.vulkan)
  set_tests_properties(${group}.${name}.vulkan PROPERTIES LABELS "vulkan;${group}" SKIP_RETURN_CODE 3
    ENVIRONMENT "${backend_test_environment}" FAIL_REGULAR_EXPRESSION "Validation (Error|Warning)|VUID-")
endforeach()

# Mutants (SPEC 7): each deliberately wrong variant must make a scene fail.
set(mutant_groups "distance-clamp-1e-4=attenuation")
foreach(entry ${mutant_groups})
  string(REPLACE "=" ";" parts ${entry})
  list(GET parts 0 mutant)
  list(GET parts 1 group)
  add_test(NAME mutants.${mutant}.vulkan
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DBACKEND=vulkan -DMUTANT=${mutant}
                   -DSCENES_DIR=${CMAKE_CURRENT_SOURCE_DIR}/scenes/${group}
                   -DEVIDENCE_DIR=${CMAKE_BINARY_DIR}/test-out/mutants/${mutant}.vulkan
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/mutant_is_killed.cmake)
  set_tests_properties(mutants.${mutant}.vulkan PROPERTIES LABELS "mutants;vulkan"
    SKIP_REGULAR_EXPRESSION "NotSupported" ENVIRONMENT "${backend_test_environment}")
endforeach()

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
set_tests_properties(cli.typo-in-scene-exits-2 cli.typo-in-scene-names-the-path cli.unknown-backend-exits-2
  cli.unknown-option-exits-2 PROPERTIES LABELS "cli")
