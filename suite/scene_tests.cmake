# ctest tests driven by the scene files, through the real `lightcts` command.
# Names follow SPEC 10: <group>.<name>.<what>; labels per group and per kind.
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
