# The scene tests' run of one backend combination (suite/scene_tests.cmake):
# `lightcts run` over every suite scene, without mutants or budgets, in one
# worker process (`--tests-per-worker`: the driver starts and compiles each
# pipeline once, where SwiftShader compiles at a pipeline's first draw in
# every process; a crash costs its test a Crash and a fresh worker carries
# on), no flake retries (a scene test checks one attempt, as `compare`
# would), then its verdicts split into one file per test for the scene tests
# to read (suite/scene_run_verdicts.py). With -DMUTANTS_ONLY=ON it is the
# mutant tests' run instead (suite/mutant_tests.cmake): the mutation check
# alone, each mutant against its killers (`run --mutants-only`), split into
# one file per mutant. Its own result is only whether the run left verdicts
# (a combination that is not here leaves NotSupported ones): a failing scene
# or a surviving mutant fails its own test, not this one.
# The combination is named by its backend and driver ("default" for the
# loader's own Vulkan driver): `--backend gl-egl` alone would run each of
# that API's Mesa drivers, every other GL combination's work again.
#   cmake -DLIGHTCTS=exe -DPYTHON=python3 -DSCENES=dir -DCOMBINATION=suffix -DBACKEND=b -DDRIVER=d -DOUT=dir
#         [-DMUTANTS_ONLY=ON] -P scene_run.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(what --no-mutants)
if(MUTANTS_ONLY)
  set(what --mutants-only)
endif()
set(driver_args)
if(NOT DRIVER STREQUAL "default")
  set(driver_args --driver ${DRIVER})
endif()
execute_process(COMMAND ${LIGHTCTS} run --backend ${BACKEND} ${driver_args} --scenes ${SCENES} ${what} --no-budgets
                        --flake-retries 0 --jobs 1 --tests-per-worker 100000 --out ${OUT}/run
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
