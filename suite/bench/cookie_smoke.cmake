# bench.cookie-smoke: render_bench --backend=vulkan (the full set: --quick
# leaves the cookie pair out) with the field at --quick's 320x180
# (--field_size: a smoke test, not a measurement) on the 64-light
# field's cookie pair (cookies on and off, SPEC 3.10 and 9) and the cookie
# upload at 256 texels a side; it must exit 0, the two frames must carry the
# load and error counters with 65 kept lights (64 point/spot, 1 directional),
# and the upload its cookie counters: 3 2D cookies, 2 cubes, 15 x 256^2
# texels (3 images and 2 x 6 faces).
# -DRENDER_BENCH=<render_bench> -DOUT=<json file>
set(RENDER_BENCH_SET "")
include(${CMAKE_CURRENT_LIST_DIR}/render_bench_smoke.cmake)
run_render_bench("^(frame/vulkan/lights64-[0-9]+x[0-9]+/cookie(s|-lights)|upload/vulkan/lights64-[0-9]+x[0-9]+/cookies/256)(/|$)"
                 --benchmark_repetitions=1 --field_size=320x180)
measured_entries()
foreach(i IN LISTS indices)
  string(JSON name GET "${json}" benchmarks ${i} name)
  if(name MATCHES "^upload/")
    require_counters(${i} cookie_textures cookie_cubes cookie_texels texels_per_s)
    string(JSON textures GET "${json}" benchmarks ${i} cookie_textures)
    string(JSON cubes GET "${json}" benchmarks ${i} cookie_cubes)
    string(JSON texels GET "${json}" benchmarks ${i} cookie_texels)
    if(NOT textures EQUAL 3 OR NOT cubes EQUAL 2 OR NOT texels EQUAL 983040)
      message(FATAL_ERROR "${name}: ${textures} 2D cookies, ${cubes} cubes, ${texels} texels: want 3, 2, 983040")
    endif()
  else()
    require_counters(${i} wall_ms pixels lights lights_per_pixel pixels_per_s pixel_light_evals_per_s ${error_counters})
    string(JSON lights GET "${json}" benchmarks ${i} lights)
    if(NOT lights EQUAL 65)
      message(FATAL_ERROR "${name}: ${lights} lights kept, not 65")
    endif()
  endif()
endforeach()
require_distinct("${names}" 3 "cookies, cookie-lights and the upload at 256")
message("ok: ${names}")
