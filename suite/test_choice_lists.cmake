# `lightcts run --list` as data: its output read back as a caselist selects
# the same tests, and the lists of --shard 1/3, 2/3 and 3/3 of a selection
# are disjoint and together the selection (SPEC 8: the selection is made
# before sharding).
#   cmake -DLIGHTCTS=exe -DSCENES=suite/scenes -DOUT=dir "-DARGS=selection arguments" -P test_choice_lists.cmake
cmake_minimum_required(VERSION 3.20)  # IN_LIST
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
function(listed variable)
  execute_process(COMMAND ${LIGHTCTS} run --list --scenes ${SCENES} ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "lightcts run --list ${ARGN} exited ${status}: ${err}")
  endif()
  string(REGEX REPLACE "\n$" "" out "${out}")
  string(REPLACE "\n" ";" names "${out}")
  set(${variable} "${names}" PARENT_SCOPE)
endfunction()

listed(selection ${ARGS})
list(LENGTH selection count)
if(count LESS 3)
  message(FATAL_ERROR "the selection lists ${count} tests; the check needs 3 or more")
endif()
string(REPLACE ";" "\n" text "${selection}")
file(WRITE ${OUT}/listed.txt "${text}\n")
listed(again --caselist ${OUT}/listed.txt)
if(NOT again STREQUAL selection)
  message(FATAL_ERROR "--list read back as a caselist selects\n${again}\ninstead of\n${selection}")
endif()

set(union)
foreach(i 1 2 3)
  listed(shard ${ARGS} --shard ${i}/3)
  foreach(name ${shard})
    if(name IN_LIST union)
      message(FATAL_ERROR "${name} is in two shards")
    endif()
  endforeach()
  list(APPEND union ${shard})
endforeach()
list(SORT union)
set(sorted ${selection})
list(SORT sorted)
if(NOT union STREQUAL sorted)
  message(FATAL_ERROR "the shards list\n${union}\nwhere the selection is\n${sorted}")
endif()
message("${count} tests: the list reads back as a caselist, and 3 shards partition it")
