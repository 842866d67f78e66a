# Parallel runs and shards (`lightcts run --jobs`, `--shard`, `lightcts merge`)
# through the real binary and real drivers:
#   MODE=jobs:   `lightcts run --jobs 1` and `--jobs 2` over the same tests (a
#                worker crash among them) write the same results, apart from
#                timings (suite/check_same_results.py).
#   MODE=shards: the same tests as one run, as 3 shards merged, and as 3
#                shards balanced by the first run's --timings merged, are the
#                same test for test; one shard of one, merged, is the run
#                itself key for key (times aside); merging shards of different revisions,
#                drivers or scene sets, with one missing or one twice exits 2
#                and writes nothing.
#   MODE=selection-shards: the same tests as one run and as 3 shards merged
#                are the same test for test, and nothing more: the
#                balancing, the shard of one and the refusals are the
#                partition's and the merge's, which MODE=shards checks on
#                its own run.
#   cmake -DLIGHTCTS=exe -DPYTHON=python3 -DCHECK=check_same_results.py -DOUT=dir -DMODE=jobs|shards|selection-shards
#         "-DARGS=run arguments" ["-DENV=K=V;..."] -P parallel_outcome.cmake
# A skip (exit 3: no backend present) prints NotSupported for ctest.
include(${CMAKE_CURRENT_LIST_DIR}/results_json.cmake)
cmake_policy(SET CMP0054 NEW)  # "shards" is a string here, not the variable below
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

# Runs `lightcts ARGV` and fails unless it exits `wanted`; sets `said` to its output.
function(lightcts wanted)
  set(command ${LIGHTCTS} ${ARGN})
  if(ENV)
    set(command ${CMAKE_COMMAND} -E env ${ENV} ${command})
  endif()
  execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(status EQUAL 3)
    message("${out}${err}")
    message("NotSupported: no backend asked for is present")
    set(skipped TRUE PARENT_SCOPE)
    return()
  endif()
  if(NOT status EQUAL wanted)
    message("${out}${err}")
    message(FATAL_ERROR "lightcts ${ARGN} exited ${status}, expected ${wanted}")
  endif()
  set(said "${out}${err}" PARENT_SCOPE)
endfunction()

function(same_results)
  execute_process(COMMAND ${PYTHON} ${CHECK} ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${ARGN}: ${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${ARGN}: they do not say the same")
  endif()
endfunction()

# A refused merge: exit 2, the reason, and no results.json in --out.
function(refused_merge reason)
  file(REMOVE_RECURSE ${OUT}/refused)
  lightcts(2 merge ${ARGN} --out ${OUT}/refused)
  if(NOT said MATCHES "${reason}")
    message(FATAL_ERROR "merge said '${said}', expected '${reason}'")
  endif()
  if(EXISTS ${OUT}/refused/results.json)
    message(FATAL_ERROR "a refused merge wrote ${OUT}/refused/results.json")
  endif()
  message("refused as expected: ${said}")
endfunction()

if(MODE STREQUAL "jobs")
  lightcts(1 run ${ARGS} --jobs 1 --out ${OUT}/jobs-1)
  if(skipped)
    return()
  endif()
  lightcts(1 run ${ARGS} --jobs 2 --out ${OUT}/jobs-2)
  if(NOT said MATCHES "up to 2 at once")
    message(FATAL_ERROR "--jobs 2 did not run two workers at once: ${said}")
  endif()
  same_results(${OUT}/jobs-1 ${OUT}/jobs-2)
  return()
endif()

lightcts(0 run ${ARGS} --out ${OUT}/whole)
if(skipped)
  return()
endif()
set(shards "")
set(balanced "")
foreach(i 1 2 3)
  lightcts(0 run ${ARGS} --shard ${i}/3 --out ${OUT}/shard-${i})
  list(APPEND shards ${OUT}/shard-${i})
  if(MODE STREQUAL "shards")
    lightcts(0 run ${ARGS} --shard ${i}/3 --timings ${OUT}/whole/results.json --out ${OUT}/balanced-${i})
    list(APPEND balanced ${OUT}/balanced-${i})
  endif()
endforeach()
lightcts(0 merge ${shards} --out ${OUT}/merged)
same_results(${OUT}/whole ${OUT}/merged)
if(MODE STREQUAL "selection-shards")
  return()
endif()
lightcts(0 merge ${balanced} --out ${OUT}/merged-balanced)
same_results(${OUT}/whole ${OUT}/merged-balanced)
# One shard of one, merged: results.json is the whole run's key for key,
# times and the merge's provenance aside (check_same_results.py --every-key).
lightcts(0 run ${ARGS} --shard 1/1 --out ${OUT}/only-shard)
lightcts(0 merge ${OUT}/only-shard --out ${OUT}/merged-only-shard)
same_results(--every-key ${OUT}/whole ${OUT}/merged-only-shard)

# Shard 2 as if from another revision (its results.json edited).
file(COPY ${OUT}/shard-2/ DESTINATION ${OUT}/other-revision)
lightcts_read_results(${OUT}/other-revision/results.json text)
string(JSON text SET "${text}" lightcts_revision "\"0000000-not-this-one\"")
file(WRITE ${OUT}/other-revision/results.json "${text}")
refused_merge("different lightcts revisions" ${OUT}/shard-1 ${OUT}/other-revision ${OUT}/shard-3)
# ... from another driver build, and over other scenes.
file(COPY ${OUT}/shard-2/ DESTINATION ${OUT}/other-driver)
lightcts_read_results(${OUT}/shard-2/results.json text)
string(JSON text SET "${text}" backends 0 device driver_version "\"99.0.0-another-build\"")
file(WRITE ${OUT}/other-driver/results.json "${text}")
refused_merge("different drivers on " ${OUT}/shard-1 ${OUT}/other-driver ${OUT}/shard-3)
file(COPY ${OUT}/shard-2/ DESTINATION ${OUT}/other-scenes)
lightcts_read_results(${OUT}/shard-2/results.json text)
string(JSON text SET "${text}" scenes_digest "\"0123\"")
file(WRITE ${OUT}/other-scenes/results.json "${text}")
refused_merge("different scene sets" ${OUT}/shard-1 ${OUT}/other-scenes ${OUT}/shard-3)
refused_merge("shard 2/3 is missing" ${OUT}/shard-1 ${OUT}/shard-3)
refused_merge("shard 3/3 is given twice" ${shards} ${OUT}/shard-3)
refused_merge("different partitions" ${OUT}/shard-1 ${OUT}/balanced-2 ${OUT}/shard-3)
refused_merge("not a shard" ${OUT}/whole)
lightcts(2 run ${ARGS} --shard 4/3 --out ${OUT}/bad-shard)
