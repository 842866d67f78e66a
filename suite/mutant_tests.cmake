# Mutant tests (SPEC 7, mutation check); included by scene_tests.cmake,
# which defines backend_combinations, split_combination and backend_test_environment.
#
# Every deliberately wrong variant of the model (shaders::mutantNames(),
# shaders/shader_interface.def) must make at least one scene fail, on every
# backend and driver: mutants.<mutant>.<backend-suffix>, labels
# "mutants;<suffix>". Each runs its killers, the scenes meant to catch it,
# from the one table suite/mutant_killers.def (the same that `lightcts run`
# checks by default).
include(${CMAKE_CURRENT_LIST_DIR}/mutant_killers.cmake)
foreach(entry ${mutant_killers})
  string(REPLACE "=" ";" mutant_parts ${entry})
  list(GET mutant_parts 0 mutant)
  list(GET mutant_parts 1 mutant_scenes)
  foreach(combination ${backend_combinations})
    split_combination(${combination})
    add_test(NAME mutants.${mutant}.${suffix}
             COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DBACKEND=${backend} -DDRIVER=${driver}
                     -DMUTANT=${mutant} -DSCENES=${mutant_scenes} -DSCENES_ROOT=${CMAKE_CURRENT_SOURCE_DIR}/scenes
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/mutant_is_killed.cmake)
    set_tests_properties(mutants.${mutant}.${suffix} PROPERTIES LABELS "mutants;${suffix}"
      SKIP_REGULAR_EXPRESSION "NotSupported" ENVIRONMENT "${backend_test_environment}")
  endforeach()
endforeach()
