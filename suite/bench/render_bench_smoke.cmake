# Shared by the bench.*-smoke scripts: run render_bench (on Vulkan unless RENDER_BENCH_BACKEND says otherwise) with
# --quick (or the set RENDER_BENCH_SET names: "" for the full set), turn "no device" into ctest's skip, and walk the JSON it wrote.
# Expects -DRENDER_BENCH=<render_bench> -DOUT=<json file>.

# Runs render_bench with `filter` and `extra` arguments; leaves the JSON in
# `json` and the number of entries in `count` (the caller's scope).
if(NOT DEFINED RENDER_BENCH_SET)
  set(RENDER_BENCH_SET --quick)
endif()
# The combination; a smoke of another one sets it before including this file.
if(NOT DEFINED RENDER_BENCH_BACKEND)
  set(RENDER_BENCH_BACKEND vulkan)
endif()
macro(run_render_bench filter)
  file(REMOVE "${OUT}")
  execute_process(
    COMMAND "${RENDER_BENCH}" --backend=${RENDER_BENCH_BACKEND} ${RENDER_BENCH_SET} --benchmark_min_time=0.01 ${ARGN}
            "--benchmark_filter=${filter}" "--benchmark_out=${OUT}" --benchmark_out_format=json
    RESULT_VARIABLE status)
  if(status EQUAL 3)
    # ctest's SKIP_REGULAR_EXPRESSION turns this into a skip.
    message(FATAL_ERROR "LIGHTCTS_SKIP: no ${RENDER_BENCH_BACKEND} here")
  endif()
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "render_bench exited with ${status}")
  endif()
  file(READ "${OUT}" json)
  string(JSON count LENGTH "${json}" benchmarks)
endmacro()

# The counters of a frame benchmark compared with its ideal reference.
set(error_counters err_rmse err_max_abs err_psnr_db err_perceptual_fail err_nonfinite_pixels)

# Sets `indices` to the entries that are measured runs (not aggregates) and
# `names` to their names, in order; fails on an entry that reports an error.
macro(measured_entries)
  set(indices "")
  set(names "")
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" benchmarks ${i} name)
    string(JSON runType GET "${json}" benchmarks ${i} run_type)
    string(JSON error ERROR_VARIABLE noError GET "${json}" benchmarks ${i} error_message)
    if(noError STREQUAL "NOTFOUND")
      message(FATAL_ERROR "${name}: ${error}")
    endif()
    if(runType STREQUAL "iteration")
      list(APPEND indices ${i})
      list(APPEND names "${name}")
    endif()
  endforeach()
endmacro()

# Fails unless entry `i` carries every counter named after it.
function(require_counters i)
  foreach(counter IN LISTS ARGN)
    string(JSON value ERROR_VARIABLE missing GET "${json}" benchmarks ${i} ${counter})
    if(NOT missing STREQUAL "NOTFOUND")
      string(JSON name GET "${json}" benchmarks ${i} name)
      message(FATAL_ERROR "${name}: no counter ${counter}")
    endif()
  endforeach()
endfunction()

# Fails unless `seen` (a list of names) holds exactly `expected` distinct ones.
function(require_distinct seen expected what)
  list(REMOVE_DUPLICATES seen)
  list(LENGTH seen distinct)
  if(NOT distinct EQUAL expected)
    message(FATAL_ERROR "expected ${expected} benchmarks (${what}), ran: ${seen}")
  endif()
endfunction()
