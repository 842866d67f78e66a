# One combination's admissible check (suite/admissible_tests.cmake): `lightcts
# run` with every admissible variant the combination realises, each against
# its witnesses (suite/admissible_witnesses.def), the expected-failures files
# applied, in one worker process (as scene_run.cmake says why). Passes when every variant is sound (exit 0);
# prints NotSupported (a ctest skip) when the backend is absent (exit 3); any
# other exit, or a validation-layer message in a worker's log, fails.
# The combination is named by its backend and driver, as in scene_run.cmake.
#   cmake -DLIGHTCTS=exe -DSCENES=dir -DCOMBINATION=suffix -DBACKEND=b -DDRIVER=d -DOUT=dir [-DEXPECTED=file,...]
#         -P admissible_run.cmake
file(REMOVE_RECURSE ${OUT})
set(driver_args)
if(NOT DRIVER STREQUAL "default")
  set(driver_args --driver ${DRIVER})
endif()
set(expected_args)
if(DEFINED EXPECTED AND NOT EXPECTED STREQUAL "")
  string(REPLACE "," ";" expected_files "${EXPECTED}")
  foreach(file ${expected_files})
    list(APPEND expected_args --expected-failures ${file})
  endforeach()
endif()
execute_process(COMMAND ${LIGHTCTS} run --backend ${BACKEND} ${driver_args} --scenes ${SCENES} --admissible all --admissible-only
                        --admissible-witnesses --no-budgets --jobs 1 --tests-per-worker 100000 ${expected_args}
                        --out ${OUT}
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(status EQUAL 3)
  message("NotSupported: no backend: ${COMBINATION} is not present here\n${output}")
  return()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/worker_logs_check.cmake)
fail_on_validation_messages(${OUT}/logs)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lightcts run exited ${status}: an admissible variant is unsound or its run broke\n${output}")
endif()
message("${output}")
