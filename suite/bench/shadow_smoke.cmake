# bench.shadow-smoke: render_bench --backend=vulkan (the full set: --quick
# leaves the shadow modes out) on one of the 64-light field's shadow modes
# (SPEC 3.9 and 9), shadows-bilinear-256 (one mode: each takes an ideal
# reference with ray-traced shadows), on the field at --quick's 320x180
# (--field_size: a smoke test, not a measurement). It must exit 0, and its
# frames carry the load and error counters with 65 kept lights (64
# point/spot, 1 directional) and the shadow passes' own time, shadow_pass_ms.
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
set(RENDER_BENCH_SET "")
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^frame/vulkan/lights64-[0-9]+x[0-9]+/shadows-bilinear-256(/|$)"
                 --benchmark_repetitions=1 --field_size=320x180)
measured_entries()
foreach(i IN LISTS indices)
  string(JSON name GET "${json}" benchmarks ${i} name)
  require_counters(${i} wall_ms pixels lights lights_per_pixel pixels_per_s shadow_pass_ms ${error_counters})
  string(JSON lights GET "${json}" benchmarks ${i} lights)
  if(NOT lights EQUAL 65)
    message(FATAL_ERROR "${name}: ${lights} lights kept, not 65")
  endif()
endforeach()
require_distinct("${names}" 1 "shadows-bilinear-256")
message("ok: ${names}")
