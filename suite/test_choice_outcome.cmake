# Choosing tests by name (SPEC 8: --include, --exclude, --caselist) through
# the real binary. `lightcts run --list` prints the tests a run would run, one
# a line; this script checks that list against one it derives itself from
# the scene files (GROUP's *.json, each on every suffix of SUFFIXES), so the
# expectation never comes from the selection code.
#   cmake -DLIGHTCTS=exe -DSCENES=suite/scenes -DGROUP=shadows "-DSUFFIXES=vulkan;gl-egl;gl-osmesa"
#         "-DARGS=run arguments" -P test_choice_outcome.cmake
execute_process(COMMAND ${LIGHTCTS} run --list --scenes ${SCENES} ${ARGS}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lightcts run --list exited ${status}")
endif()
string(REGEX REPLACE "\n$" "" out "${out}")
string(REPLACE "\n" ";" lines "${out}")
set(listed)
foreach(line ${lines})
  list(APPEND listed "${line}")
endforeach()

file(GLOB scene_files ${SCENES}/${GROUP}/*.json)
set(expected)
foreach(suffix ${SUFFIXES})
  foreach(file ${scene_files})
    get_filename_component(name ${file} NAME_WE)
    list(APPEND expected "${GROUP}.${name}.${suffix}")
  endforeach()
endforeach()
list(SORT listed)
list(SORT expected)
list(LENGTH expected count)
if(count EQUAL 0)
  message(FATAL_ERROR "no scene in ${SCENES}/${GROUP}")
endif()
if(NOT listed STREQUAL expected)
  message(FATAL_ERROR "the run lists\n${listed}\nexpected exactly\n${expected}")
endif()
message("exactly the ${count} expected tests")
