# The build with CMake's default generator, Unix Makefiles, as a new user
# runs it (`cmake -S . -B build && cmake --build build`), cut down to the
# generated shader code (lightcts_shader_code: glslangValidator and
# spirv-cross, which do not create the folders they write into; the other
# generated headers are written by CMake scripts, which do): Ninja creates the
# folders of a custom command's outputs, Make does not, so a command that writes into a
# folder nobody created only fails here. Nothing is compiled: the C++ build
# is the same under both generators. Tests and benchmarks are not
# configured, which only adds tests. A fresh folder every time, so nothing
# left from a previous run hides a missing step.
#
#   cmake -DSOURCE_DIR=<repository> -DWORK=<empty folder to use> -P makefiles_build_test.cmake
if(NOT SOURCE_DIR OR NOT WORK)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=... -DWORK=... -P makefiles_build_test.cmake")
endif()

file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK}" -G "Unix Makefiles"
                        -DLIGHTCTS_BUILD_TESTS=OFF -DLIGHTCTS_BUILD_BENCHMARKS=OFF
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "configure with Unix Makefiles failed (${status}):\n${output}")
endif()

execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK}" --target lightcts_shader_code -j2
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "building lightcts_shader_code with Unix Makefiles failed (${status}):\n${output}")
endif()
foreach(generated spirv/forward_vert.h spirv/forward_vert.spv glsl330/forward_vert.h
                  reflection/forward_vert.json layout/shader_layout_assertions.h)
  if(NOT EXISTS "${WORK}/shaders/${generated}")
    message(FATAL_ERROR "the Makefiles build did not write shaders/${generated}")
  endif()
endforeach()
message(STATUS "Unix Makefiles: configured and made lightcts_shader_code in ${WORK}")
