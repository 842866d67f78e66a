# bench.error-cache-smoke: the errors kept across runs (--error_cache,
# docs/bench-format.md). render_bench --quick draws the field's all-lights
# frame three times, each with an empty --ideal_cache of its own:
#  1. an empty error cache: the ideal is rendered (its file appears), the
#     error computed and kept (one .error file under DIR/<fingerprint>/);
#  2. the same error cache: the same counters, and no ideal rendered (the
#     frame reads back bit for bit the same, so its error is known);
#  3. the kept file damaged: a miss, the ideal rendered again, the same counters.
# -DRENDER_BENCH=<render_bench> -DOUT=<json file> -DWORK=<scratch folder>
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
file(REMOVE_RECURSE "${WORK}")
set(filter "^frame/vulkan/lights64-[0-9]+x[0-9]+/all-lights(/|$)")

# Sets `errors` to the all-lights entry's error counters, as text.
macro(read_errors)
  measured_entries()
  list(GET indices 0 first)
  set(errors "")
  foreach(counter IN LISTS error_counters)
    string(JSON value GET "${json}" benchmarks ${first} ${counter})
    list(APPEND errors "${counter}=${value}")
  endforeach()
endmacro()

function(require_ideals folder expected what)
  file(GLOB ideals "${folder}/*.ideal")
  list(LENGTH ideals n)
  if(NOT n EQUAL expected)
    message(FATAL_ERROR "${what}: ${n} ideal references rendered, expected ${expected}")
  endif()
endfunction()

run_render_bench("${filter}" "--ideal_cache=${WORK}/ideal1" "--error_cache=${WORK}/errors")
read_errors()
set(firstErrors "${errors}")
require_ideals("${WORK}/ideal1" 1 "an empty error cache")
file(GLOB_RECURSE kept "${WORK}/errors/*.error")
list(LENGTH kept keptCount)
if(NOT keptCount EQUAL 1)
  message(FATAL_ERROR "expected one kept error under ${WORK}/errors, found ${keptCount}: ${kept}")
endif()

run_render_bench("${filter}" "--ideal_cache=${WORK}/ideal2" "--error_cache=${WORK}/errors")
read_errors()
if(NOT errors STREQUAL firstErrors)
  message(FATAL_ERROR "a kept error differs: ${errors} against ${firstErrors}")
endif()
require_ideals("${WORK}/ideal2" 0 "a kept error")

file(WRITE "${kept}" "0.5 not-a-number\n")
run_render_bench("${filter}" "--ideal_cache=${WORK}/ideal3" "--error_cache=${WORK}/errors")
read_errors()
if(NOT errors STREQUAL firstErrors)
  message(FATAL_ERROR "after a damaged file: ${errors} against ${firstErrors}")
endif()
require_ideals("${WORK}/ideal3" 1 "a damaged kept error")
file(REMOVE_RECURSE "${WORK}")
message("ok: ${firstErrors}")
