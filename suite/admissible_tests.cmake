# Admissible variant tests (SPEC 7); included by scene_tests.cmake, which
# defines backend_combinations, split_combination, expected_failures_files
# and backend_test_environment.
#
# Every deliberately different but legal implementation
# (shaders/shader_interface.def) must pass the scenes it brings closest to
# their tolerance, its witnesses (suite/admissible_witnesses.def), on every
# combination that realises it: admissible.<suffix>, one `lightcts run` per
# combination, labels "admissible;<suffix>". The whole sweep, every variant
# against every scene, is `lightcts run --admissible all --admissible-only`
# (docs/vendors.md).
set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_LIST_DIR}/admissible_witnesses.def)
string(REPLACE ";" "," admissible_expected "${expected_failures_files}")
foreach(combination ${backend_combinations})
  split_combination(${combination})
  add_test(NAME admissible.${suffix}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DSCENES=${CMAKE_CURRENT_SOURCE_DIR}/scenes
                   -DCOMBINATION=${suffix} -DBACKEND=${backend} -DDRIVER=${driver} -DOUT=${CMAKE_BINARY_DIR}/test-out/admissible/${suffix}
                   -DEXPECTED=${admissible_expected} -P ${CMAKE_CURRENT_SOURCE_DIR}/admissible_run.cmake)
  # COST: started first (CMakeLists.txt says why): SwiftShader's compiles each
  # variant's pipelines, one of the suite's long tests.
  set_tests_properties(admissible.${suffix} PROPERTIES LABELS "admissible;${suffix}"
    SKIP_REGULAR_EXPRESSION "NotSupported: no backend" ENVIRONMENT "${backend_test_environment}" COST 40)
endforeach()
