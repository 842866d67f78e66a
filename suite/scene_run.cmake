# The scene tests' run of one backend combination (suite/scene_tests.cmake):
# `lightcts run` over every suite scene, without mutants or budgets, one
# worker at a time (a fresh one every 24 scenes), no flake retries (a scene test checks one attempt, as `compare`
# would), then its verdicts split into one file per test for the scene tests
# to read (suite/scene_run_verdicts.py). Its own result is only whether the
# run left verdicts (a combination that is not here leaves NotSupported ones): a failing scene
# fails its own test, not this one.
#   cmake -DLIGHTCTS=exe -DPYTHON=python3 -DSCENES=dir -DCOMBINATION=suffix -DOUT=dir -P scene_run.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${LIGHTCTS} run --backend ${COMBINATION} --scenes ${SCENES} --no-mutants --no-budgets
                        --flake-retries 0 --jobs 1 --out ${OUT}/run
                RESULT_VARIABLE status OUTPUT_FILE ${OUT}/run.log ERROR_FILE ${OUT}/run.log)
file(READ ${OUT}/run.log log)
message("lightcts run exited ${status}:\n${log}")
# A validation-layer message fails its test (the worker reports a Crash);
# one that no draw threw (said at start-up or shutdown) is in the workers'
# logs, and fails every test of the combination here.
include(${CMAKE_CURRENT_LIST_DIR}/worker_logs_check.cmake)
fail_on_validation_messages(${OUT}/run/logs)
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/scene_run_verdicts.py ${OUT}/run ${OUT}/verdicts
                RESULT_VARIABLE split)
if(NOT split EQUAL 0)
  message(FATAL_ERROR "the run of ${COMBINATION} left no verdicts to read")
endif()
