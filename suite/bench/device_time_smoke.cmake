# bench.device-time-that-misses-work-is-wall-timed: with the device's time
# forced (--time_source=device), every iteration is either plausible (its
# device time at least half its wall time, and then the entry's time is the
# device's) or flagged (device_time_flagged, a label beginning "wall time",
# and the entry's time is the wall time, never the device's). llvmpipe's
# GL_TIME_ELAPSED misses most of a light frame, so the one-light entries must
# be flagged; how much of the 64-light frame it covers varies with the
# machine's load, so that entry is held to the rule, whichever
# side it falls on. (--quick runs one repetition of one iteration; were there
# more, a repetition after a flagged one is wall-timed too, with
# device_time_flagged 0 and a label that says why.)
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
set(RENDER_BENCH_BACKEND gl-egl)
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^frame/gl-egl/curve-lights/all-lights/(1|64)(/|$)" --time_source=device)

# Whether |a - b| <= 1 % of b, or a >= b * share: evaluated in Python (CMake
# has no floating point).
function(holds expression a b out)
  execute_process(COMMAND ${PYTHON} -c
    "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(0 if (${expression}) else 1)" ${a} ${b}
    RESULT_VARIABLE status)
  if(status EQUAL 0)
    set(${out} TRUE PARENT_SCOPE)
  else()
    set(${out} FALSE PARENT_SCOPE)
  endif()
endfunction()

math(EXPR last "${count} - 1")
set(checked 0)
set(flaggedOneLight 0)
foreach(i RANGE ${last})
  string(JSON name GET "${json}" benchmarks ${i} name)
  string(JSON runType GET "${json}" benchmarks ${i} run_type)
  if(NOT runType STREQUAL "iteration")
    continue()
  endif()
  string(JSON iterations GET "${json}" benchmarks ${i} iterations)
  if(NOT iterations EQUAL 1)
    # The rule is per iteration; with one the entry's means are that iteration.
    message(FATAL_ERROR "${name}: ${iterations} iterations; the check needs one")
  endif()
  string(JSON realTime GET "${json}" benchmarks ${i} real_time)
  string(JSON wallMs GET "${json}" benchmarks ${i} wall_ms)
  string(JSON device GET "${json}" benchmarks ${i} device_ms)
  string(JSON label ERROR_VARIABLE noLabel GET "${json}" benchmarks ${i} label)
  string(JSON flagged ERROR_VARIABLE notFlagged GET "${json}" benchmarks ${i} device_time_flagged)
  # The rule, stated again here rather than read from the code: a device
  # time is plausible when it is at least half the wall time
  # (kLeastDeviceShareOfWall, suite/bench/time_source.h, derives the margin).
  holds("a >= 0.5 * b" ${device} ${wallMs} plausible)
  if(notFlagged STREQUAL "NOTFOUND")
    if(NOT label MATCHES "^wall time")
      message(FATAL_ERROR "${name}: flagged, but label '${label}' does not say the entry is wall-timed")
    endif()
    holds("abs(a - b) <= 0.01 * b" ${realTime} ${wallMs} isWall)
    if(NOT isWall)
      message(FATAL_ERROR "${name}: flagged, but real_time ${realTime} ms is not the wall time ${wallMs} ms (device ${device} ms)")
    endif()
    # A count of 0 is a later repetition of a benchmark an earlier one
    # flagged: wall-timed whatever its own device time.
    if(flagged GREATER 0 AND plausible)
      message(FATAL_ERROR "${name}: flagged, but device ${device} ms is at least half the wall time ${wallMs} ms")
    endif()
    if(name MATCHES "/all-lights/1(/|$)")
      math(EXPR flaggedOneLight "${flaggedOneLight} + 1")
    endif()
    message("ok (flagged): ${name}: ${label}; real_time ${realTime} ms = wall ${wallMs} ms (device ${device} ms)")
  else()
    if(NOT plausible)
      message(FATAL_ERROR "${name}: device ${device} ms is below half the wall time ${wallMs} ms and went unflagged")
    endif()
    holds("abs(a - b) <= 0.01 * b" ${realTime} ${device} isDevice)
    if(NOT isDevice)
      message(FATAL_ERROR "${name}: real_time ${realTime} ms is not the device time ${device} ms (wall ${wallMs} ms)")
    endif()
    message("ok (device-timed): ${name}: real_time ${realTime} ms = device ${device} ms (wall ${wallMs} ms)")
  endif()
  math(EXPR checked "${checked} + 1")
endforeach()
if(checked LESS 2)
  message(FATAL_ERROR "only ${checked} entries checked (two benchmarks expected)")
endif()
if(flaggedOneLight LESS 1)
  message(FATAL_ERROR "the one-light entry is not flagged: llvmpipe's timer missed nothing, or the flag did not fire")
endif()
