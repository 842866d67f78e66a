# Reads the one table of backend combinations (backend_combinations.def, which
# C++ includes too) into `backend_combinations`: a list of
# "<suffix>=<backend>=<driver>", with "default" for an empty driver, so that
# ctest's names and labels come from the same lines as the runner's.
set(backend_combinations_table ${CMAKE_CURRENT_LIST_DIR}/backend_combinations.def)
set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${backend_combinations_table})
file(STRINGS ${backend_combinations_table} backend_combination_lines REGEX "^LIGHTCTS_COMBINATION\\(")
set(backend_combinations)
foreach(line ${backend_combination_lines})
  if(NOT line MATCHES "^LIGHTCTS_COMBINATION\\(\"([a-z0-9-]+)\", *\"([a-z0-9-]+)\", *\"([a-z0-9-]*)\"\\)$")
    message(FATAL_ERROR "${backend_combinations_table}: cannot read '${line}'")
  endif()
  set(combination_driver "${CMAKE_MATCH_3}")
  if("${combination_driver}" STREQUAL "")
    set(combination_driver default)
  endif()
  list(APPEND backend_combinations "${CMAKE_MATCH_1}=${CMAKE_MATCH_2}=${combination_driver}")
endforeach()
list(LENGTH backend_combinations backend_combination_count)
if(backend_combination_count EQUAL 0)
  message(FATAL_ERROR "${backend_combinations_table}: no combination")
endif()
