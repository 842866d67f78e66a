# bench.frame-smoke: render_bench --backend=vulkan --quick on the 64-light
# field's all-lights frame (its error counters need the ideal reference, the
# longest part) and one curve point; it must exit
# 0 and its JSON must carry the counters of docs/bench-format.md.
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^frame/vulkan/(lights64-[0-9]+x[0-9]+/all-lights|curve-lights/all-lights/64)(/|$)" --peak_gflops=10)
measured_entries()
foreach(i IN LISTS indices)
  string(JSON name GET "${json}" benchmarks ${i} name)
  set(required wall_ms pixels lights lights_per_pixel pixels_per_s pixel_light_evals_per_s limit_ms flops_per_pixel_light)
  if(name MATCHES "^frame/vulkan/lights64-[0-9]+x[0-9]+/")
    list(APPEND required ${error_counters})
  endif()
  require_counters(${i} ${required})
  string(JSON lights GET "${json}" benchmarks ${i} lights)
  if(NOT lights EQUAL 64)
    message(FATAL_ERROR "${name}: ${lights} lights kept, not 64")
  endif()
endforeach()
require_distinct("${names}" 2 "the all-lights field frame and one curve point")
message("ok: ${names}")
