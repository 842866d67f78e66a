# Mutant tests (SPEC 7, mutation check); included by scene_tests.cmake,
# which defines backend_combinations, split_combination and backend_test_environment.
#
# Every deliberately wrong variant of the model (shaders::mutantNames(),
# shaders/shader_interface.def) must make at least one scene fail, on every
# backend and driver: mutants.<mutant>.<backend-suffix>, labels
# "mutants;<suffix>". Each combination checks every mutant against its
# killers, the scenes meant to catch it (the one table
# suite/mutant_killers.def, which `lightcts run` checks by default), in one
# `lightcts run --mutants-only` (mutant-runs.<suffix>, in one worker process
# as suite/scene_run.cmake says), so a driver starts once per combination,
# not once per mutant; each mutant's test reads
# its status from that run: killed passes (a killer failed the comparison
# with it and passes without); survived (no killer did), Crash or Timeout (a
# driver error or a validation message, with no killer's comparison
# failing: a mutant must be killed by the comparison, not by a crash) fails;
# NotSupported is a skip.
include(${CMAKE_CURRENT_LIST_DIR}/mutant_killers.cmake)
foreach(combination ${backend_combinations})
  split_combination(${combination})
  add_test(NAME mutant-runs.${suffix}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DPYTHON=${LIGHTCTS_PYTHON3}
                   -DSCENES=${CMAKE_CURRENT_SOURCE_DIR}/scenes -DCOMBINATION=${suffix} -DBACKEND=${backend} -DDRIVER=${driver} -DMUTANTS_ONLY=ON
                   -DOUT=${CMAKE_BINARY_DIR}/test-out/mutant-runs/${suffix} -P ${CMAKE_CURRENT_SOURCE_DIR}/scene_run.cmake)
  set_tests_properties(mutant-runs.${suffix} PROPERTIES LABELS "mutants;mutant-runs;${suffix}"
    FIXTURES_SETUP mutant-run-${suffix} ENVIRONMENT "${backend_test_environment}" TIMEOUT 1500 COST 20)
endforeach()
foreach(mutant ${mutant_names})
  foreach(combination ${backend_combinations})
    split_combination(${combination})
    add_test(NAME mutants.${mutant}.${suffix}
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/scene_verdict.sh ${CMAKE_BINARY_DIR}/test-out/mutant-runs/${suffix}/verdicts
                     mutants.${mutant}.${suffix} killed)
    set_tests_properties(mutants.${mutant}.${suffix} PROPERTIES LABELS "mutants;${suffix}" SKIP_RETURN_CODE 77
      FIXTURES_REQUIRED mutant-run-${suffix})
  endforeach()
endforeach()
