# The test unit.scenes.deferred-variants-match-originals: every generated
# deferred variant in scenes/deferred/ is its original with exactly the
# three changes of scenes/deferred/variants.cmake (README.md), compared as
# parsed JSON. Fails for a missing variant, a hand-edited one, or a stale one
# (an original edited since the last configure).
#   cmake -DSCENES=<suite/scenes> -P check_deferred_variants.cmake
cmake_minimum_required(VERSION 3.25)  # string(JSON), and the policies of the project
if(NOT DEFINED SCENES)
  message(FATAL_ERROR "usage: cmake -DSCENES=<suite/scenes> -P check_deferred_variants.cmake")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/deferred_variants.cmake)
lightcts_check_deferred_variants("${SCENES}" problems)
if(problems)
  message(FATAL_ERROR "deferred variants that do not match their originals:\n${problems}")
endif()
message(STATUS "${problems_COUNT} deferred variants match their originals")
