# SPEC 7: a comparison must be able to fail. The scenes of
# suite/vacuous-scenes/vacuous/ (not suite scenes): a black one and an
# all-masked one are QualityWarning with their reasons, the same scene lit
# is a Pass; through `compare` (exit 0, the reason printed) and through `run`
# (results.json, junit.xml as <skipped>, the report). Label `vacuous`.
set(vacuous_scenes ${CMAKE_CURRENT_SOURCE_DIR}/vacuous-scenes/vacuous)
foreach(case "black;no compared pixel of the reference is above the flush-to-zero floor"
              "all-masked;only 0 of 256 pixels are compared")
  list(GET case 0 name)
  list(GET case 1 reason)
  add_test(NAME vacuous.${name}-compare-is-quality-warning
           COMMAND lightcts compare --scene ${vacuous_scenes}/${name}.json --backend vulkan --no-evidence)
  set_tests_properties(vacuous.${name}-compare-is-quality-warning PROPERTIES LABELS "vacuous;vulkan"
    SKIP_RETURN_CODE 3 ENVIRONMENT "${backend_test_environment}"
    PASS_REGULAR_EXPRESSION "(^|\n)QualityWarning vacuous\\.${name}\\.vulkan: .*\n  QualityWarning: ${reason}")
endforeach()
add_test(NAME vacuous.lit-compare-passes
         COMMAND lightcts compare --scene ${vacuous_scenes}/lit.json --backend vulkan --no-evidence)
set_tests_properties(vacuous.lit-compare-passes PROPERTIES LABELS "vacuous;vulkan" SKIP_RETURN_CODE 3
  ENVIRONMENT "${backend_test_environment}" PASS_REGULAR_EXPRESSION "(^|\n)Pass vacuous\\.lit\\.vulkan: "
  FAIL_REGULAR_EXPRESSION "QualityWarning")
add_test(NAME vacuous.run-counts-quality-warnings
         COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DSCENES=${vacuous_scenes}
                 -DOUT=${CMAKE_BINARY_DIR}/test-out/vacuous-run -P ${CMAKE_CURRENT_SOURCE_DIR}/vacuous_outcome.cmake)
set_tests_properties(vacuous.run-counts-quality-warnings PROPERTIES LABELS "vacuous;run;vulkan"
  SKIP_REGULAR_EXPRESSION "NotSupported: no backend" ENVIRONMENT "${backend_test_environment}")
