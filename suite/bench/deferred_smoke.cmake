# bench.deferred-smoke: render_bench --backend=vulkan --quick on the 64-light
# field's three deferred modes and one deferred curve point; it must exit 0,
# every entry must carry the load counters with the volumes' own light count
# (lights_per_pixel below the 64 kept lights: docs/bench-format.md), the field
# modes the error counters, and ldr8 (its decode saturates at log2(255) under
# the brightest lights) must be further from the ideal reference than hdr32.
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^frame/vulkan/(lights64-[0-9]+x[0-9]+/deferred-(hdr32|hdr16|ldr8)|curve-lights/deferred-hdr32/64)(/|$)" --benchmark_repetitions=1)
set(rmse_hdr32 "")
set(rmse_ldr8 "")
measured_entries()
foreach(i IN LISTS indices)
  string(JSON name GET "${json}" benchmarks ${i} name)
  set(required wall_ms pixels lights lights_per_pixel pixels_per_s pixel_light_evals_per_s)
  if(name MATCHES "/lights64-[0-9]+x[0-9]+/")
    list(APPEND required ${error_counters})
  endif()
  require_counters(${i} ${required})
  string(JSON lights GET "${json}" benchmarks ${i} lights)
  string(JSON perPixel GET "${json}" benchmarks ${i} lights_per_pixel)
  if(NOT lights EQUAL 64)
    message(FATAL_ERROR "${name}: ${lights} lights kept, not 64")
  endif()
  if(NOT perPixel GREATER 0 OR NOT perPixel LESS 64)
    message(FATAL_ERROR "${name}: lights_per_pixel ${perPixel}: want the volumes that cover a pixel, in (0, 64)")
  endif()
  if(name MATCHES "/lights64-[0-9]+x[0-9]+/deferred-hdr32$")
    string(JSON rmse_hdr32 GET "${json}" benchmarks ${i} err_rmse)
  elseif(name MATCHES "/lights64-[0-9]+x[0-9]+/deferred-ldr8$")
    string(JSON rmse_ldr8 GET "${json}" benchmarks ${i} err_rmse)
  endif()
endforeach()
require_distinct("${names}" 4 "three deferred modes, one curve point")
if(NOT rmse_hdr32 LESS rmse_ldr8)
  message(FATAL_ERROR "err_rmse: hdr32 ${rmse_hdr32} is not below ldr8 ${rmse_ldr8}")
endif()
message("ok: ${names}; err_rmse hdr32 ${rmse_hdr32}, ldr8 ${rmse_ldr8}")
