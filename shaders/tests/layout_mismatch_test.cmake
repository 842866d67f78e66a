# A std140 block laid out otherwise in the GLSL than in the C++ fails the
# build. The shader sources are copied to WORK and run through the build's
# own steps (glslang, spirv-cross --reflect, shader_layout_checks.cmake, then
# the compile of shaders/shader_layout_checks.cpp), first unchanged, which
# must compile, then with one change each, which must fail naming the block
# and the member:
#   moved:    FrameBlock's cameraPosition and view exchanged (an offset);
#   retyped:  FrameBlock.ambient an ivec4 (a type of the same size);
#   unmapped: a member added to FrameBlock that no C++ member stands for;
#   nested:   Light's color and spotDirection exchanged (a struct inside a block).
# And a block no table line names stops the generator itself.
#
#   cmake -DSOURCE_DIR=<repository> -DWORK=<folder> -DCXX=<compiler>
#         -DGLSLANG=<glslangValidator> -DSPIRV_CROSS=<spirv-cross> -P layout_mismatch_test.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var SOURCE_DIR WORK CXX GLSLANG SPIRV_CROSS)
  if(NOT ${var})
    message(FATAL_ERROR "layout_mismatch_test.cmake: ${var} is not set")
  endif()
endforeach()

set(table "${SOURCE_DIR}/shaders/shader_interface.def")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/generated/glsl" "${WORK}/generated/shaders")
execute_process(COMMAND "${CMAKE_COMMAND}" -DSHADER_INTERFACE_TABLE=${table}
                        -DSHADER_INTERFACE_GLSL=${WORK}/generated/glsl/shader_interface.glsl
                        -DSHADER_INTERFACE_HEADER=${WORK}/generated/shaders/shader_interface.h
                        -P "${SOURCE_DIR}/shaders/shader_interface.cmake"
                RESULT_VARIABLE status ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the generator failed:\n${output}")
endif()
file(GLOB stages RELATIVE "${SOURCE_DIR}/shaders" "${SOURCE_DIR}/shaders/*.vert" "${SOURCE_DIR}/shaders/*.frag")
file(GLOB includes "${SOURCE_DIR}/shaders/*.glsl")

# One case: the sources with `from` replaced by `to` in `file`; sets
# `case_status` (0 when the layout checks compiled) and `case_output`.
function(run_case name file from to)
  set(dir "${WORK}/${name}")
  file(MAKE_DIRECTORY "${dir}/src" "${dir}/spirv")
  foreach(source ${stages})
    file(COPY "${SOURCE_DIR}/shaders/${source}" DESTINATION "${dir}/src")
  endforeach()
  file(COPY ${includes} DESTINATION "${dir}/src")
  if(file)
    file(READ "${dir}/src/${file}" text)
    string(FIND "${text}" "${from}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "case ${name}: ${file} has no '${from}' to change")
    endif()
    string(REPLACE "${from}" "${to}" text "${text}")
    file(WRITE "${dir}/src/${file}" "${text}")
  endif()
  set(reflections)
  foreach(source ${stages})
    string(REPLACE "." "_" symbol ${source})
    execute_process(COMMAND "${GLSLANG}" --quiet -V --target-env vulkan1.1 -I${WORK}/generated/glsl
                            -o ${dir}/spirv/${symbol}.spv ${dir}/src/${source}
                    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "case ${name}: glslang refused ${source}:\n${output}")
    endif()
    execute_process(COMMAND "${SPIRV_CROSS}" ${dir}/spirv/${symbol}.spv --reflect --output ${dir}/spirv/${symbol}.json
                    RESULT_VARIABLE status ERROR_VARIABLE output)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "case ${name}: spirv-cross --reflect failed on ${source}:\n${output}")
    endif()
    list(APPEND reflections ${dir}/spirv/${symbol}.json)
  endforeach()
  execute_process(COMMAND "${CMAKE_COMMAND}" -DSHADER_INTERFACE_TABLE=${table} "-DREFLECTIONS=${reflections}"
                          -DOUTPUT=${dir}/shader_layout_assertions.h
                          -P "${SOURCE_DIR}/shaders/shader_layout_checks.cmake"
                  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(status EQUAL 0)
    execute_process(COMMAND "${CXX}" -std=c++20 -fsyntax-only -I${dir} -I${SOURCE_DIR}
                            ${SOURCE_DIR}/shaders/shader_layout_checks.cpp
                    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  endif()
  set(case_status ${status} PARENT_SCOPE)
  set(case_output "${output}" PARENT_SCOPE)
endfunction()

function(expect_failure name file from to message)
  run_case(${name} "${file}" "${from}" "${to}")
  if(case_status EQUAL 0)
    message(FATAL_ERROR "case ${name}: ${file} changed ('${from}' -> '${to}') and the layout checks still compiled")
  endif()
  string(FIND "${case_output}" "${message}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "case ${name} failed, but without naming '${message}':\n${case_output}")
  endif()
  message(STATUS "case ${name}: fails, naming ${message}")
endfunction()

run_case(unchanged "" "" "")
if(NOT case_status EQUAL 0)
  message(FATAL_ERROR "the unchanged shaders fail the layout checks:\n${case_output}")
endif()

set(camera "  vec4 cameraPosition;  // xyz: the camera position in float, w: 1; read only by the absolute-coordinates mutants\n")
set(view "  vec4 view;            // SPEC 3.8: xyz the orthographic V; w 1 orthographic, 0 perspective (V = normalize(-p))\n")
expect_failure(moved light_data.glsl "${camera}${view}" "${view}${camera}" "FrameBlock.cameraPosition: at offset")
expect_failure(retyped light_data.glsl "  vec4 ambient;\n" "  ivec4 ambient;\n" "FrameBlock.ambient: ivec4")
expect_failure(unmapped light_data.glsl "  ivec4 opaqueZero;" "  ivec4 opaqueZero;\n  vec4 unmappedMember;"
               "FrameBlock.unmappedMember")
set(color "  vec4 color;          // rgb: finalColor; w: invRangeSq\n")
set(spot "  vec4 spotDirection;  // xyz: spotDir = -direction; w: cookie slot in CookieBlock, or -1\n")
expect_failure(nested light_data.glsl "${color}${spot}" "${spot}${color}" "Light.color: at offset")
# (CMake wraps the generator's message: only a word of it is sure to be whole.)
expect_failure(untabled deferred_data.glsl "uniform DeferredFrameBlock {" "uniform UntabledBlock {" "UntabledBlock")
