# Reads the mutant names of the mutation check's one table (mutant_killers.def,
# which C++ includes too, and whose killers `lightcts run --mutants-only`
# checks) into `mutant_names`, so that ctest has a mutants.<mutant>.<backend>
# test for every line of the table.
set(mutant_killers_table ${CMAKE_CURRENT_LIST_DIR}/mutant_killers.def)
set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${mutant_killers_table})
file(STRINGS ${mutant_killers_table} mutant_killer_lines REGEX "^LIGHTCTS_MUTANT_KILLERS\\(")
set(mutant_names)
foreach(line ${mutant_killer_lines})
  if(NOT line MATCHES "^LIGHTCTS_MUTANT_KILLERS\\(\"([a-z0-9-]+)\", *\"([a-z0-9. -]+)\"\\)$")
    message(FATAL_ERROR "${mutant_killers_table}: cannot read '${line}'")
  endif()
  list(APPEND mutant_names "${CMAKE_MATCH_1}")
endforeach()
list(LENGTH mutant_names mutant_count)
if(mutant_count EQUAL 0)
  message(FATAL_ERROR "${mutant_killers_table}: no mutant")
endif()
