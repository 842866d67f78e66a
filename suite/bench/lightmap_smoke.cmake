# bench.lightmap-smoke: render_bench --backend=vulkan --quick on the lightmap
# scene's realtime and lightmap-16 frames (320x180 with --quick); it must
# exit 0, every entry must carry the error counters (against the lights in
# real time), and lightmap-16 also bake_ms > 0 and lightmap_texels = 256.
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^frame/vulkan/lightmap-[0-9]+x[0-9]+/(realtime|lightmap-16)(/|$)" --benchmark_repetitions=1)
measured_entries()
foreach(i IN LISTS indices)
  string(JSON name GET "${json}" benchmarks ${i} name)
  set(required wall_ms pixels ${error_counters})
  if(name MATCHES "/lightmap-16$")
    list(APPEND required bake_ms bake_runs lightmap_texels)
  endif()
  require_counters(${i} ${required})
  if(name MATCHES "/lightmap-16$")
    string(JSON bake GET "${json}" benchmarks ${i} bake_ms)
    string(JSON texels GET "${json}" benchmarks ${i} lightmap_texels)
    if(NOT bake GREATER 0 OR NOT texels EQUAL 256)
      message(FATAL_ERROR "${name}: bake_ms ${bake}, lightmap_texels ${texels} (want > 0 and 256)")
    endif()
  endif()
endforeach()
require_distinct("${names}" 2 "realtime, lightmap-16")
message("ok: ${names}")
