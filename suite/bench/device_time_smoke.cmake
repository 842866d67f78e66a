# bench.device-time-that-misses-work-is-wall-timed: llvmpipe's GL_TIME_ELAPSED
# covers about a tenth of a frame (suite/bench/time_source.h), so with the
# device's time forced (--time_source=device) every gl-egl frame's device time
# is below half its wall time: each entry must say so (device_time_flagged,
# a label beginning "wall time") and report its wall time, never the device's.
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
set(RENDER_BENCH_BACKEND gl-egl)
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^frame/gl-egl/curve-lights/all-lights/(1|64)(/|$)" --time_source=device --benchmark_repetitions=2)
math(EXPR last "${count} - 1")
set(checked 0)
foreach(i RANGE ${last})
  string(JSON name GET "${json}" benchmarks ${i} name)
  string(JSON runType GET "${json}" benchmarks ${i} run_type)
  if(NOT runType STREQUAL "iteration")
    continue()
  endif()
  string(JSON flagged ERROR_VARIABLE missing GET "${json}" benchmarks ${i} device_time_flagged)
  if(NOT missing STREQUAL "NOTFOUND")
    message(FATAL_ERROR "${name}: no device_time_flagged counter: a device time that missed the work went unflagged")
  endif()
  string(JSON label GET "${json}" benchmarks ${i} label)
  if(NOT label MATCHES "^wall time")
    message(FATAL_ERROR "${name}: label '${label}' does not say the entry is wall-timed")
  endif()
  string(JSON realTime GET "${json}" benchmarks ${i} real_time)
  string(JSON wallMs GET "${json}" benchmarks ${i} wall_ms)
  string(JSON device ERROR_VARIABLE noDevice GET "${json}" benchmarks ${i} device_ms)
  # real_time (ms) must be the wall time: the mean of the iterations' wall times.
  execute_process(COMMAND /usr/bin/python3 -c
    "import sys; r, w = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if abs(r - w) <= 0.01 * w else 1)"
    ${realTime} ${wallMs} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${name}: real_time ${realTime} ms is not the wall time ${wallMs} ms (device ${device} ms)")
  endif()
  message("ok: ${name}: ${label}; real_time ${realTime} ms = wall ${wallMs} ms (device ${device} ms)")
  math(EXPR checked "${checked} + 1")
endforeach()
if(checked LESS 2)
  message(FATAL_ERROR "only ${checked} entries checked")
endif()
