# Adding a mutant or a texture binding is one line in shaders/shader_interface.def:
# the table copied to WORK with one line appended (KIND mutant: a shader
# mutant with the next number; KIND texture: two samplers in a set and at
# texture units no other entry uses), the generator run on it, and the new
# entry checked in every output: the GLSL constant or binding macros and the
# C++ enumerator, name table and bindings, in the text and by compiling a
# C++ file (static_asserts on the values) and a fragment shader that uses
# them (glslang, then spirv-cross --reflect for the sampler's set and binding).
#
#   cmake -DSOURCE_DIR=<repository> -DWORK=<folder> -DKIND=mutant|texture -DCXX=<compiler>
#         -DGLSLANG=<glslangValidator> -DSPIRV_CROSS=<spirv-cross> -P one_line_test.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var SOURCE_DIR WORK KIND CXX GLSLANG SPIRV_CROSS)
  if(NOT ${var})
    message(FATAL_ERROR "one_line_test.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/generated/glsl" "${WORK}/generated/shaders")
set(table "${WORK}/shader_interface.def")
file(READ "${SOURCE_DIR}/shaders/shader_interface.def" text)
file(STRINGS "${SOURCE_DIR}/shaders/shader_interface.def" mutant_lines REGEX "^LIGHTCTS_MUTANT\\(")
list(LENGTH mutant_lines mutant_count)
math(EXPR number "${mutant_count} + 1")

if(KIND STREQUAL "mutant")
  set(line "LIGHTCTS_MUTANT(${number}, \"one-line-test\", shader, \"the mutant this test adds\")")
  set(glsl_expected "const int MUTANT_ONE_LINE_TEST = ${number};")
  set(cpp_expected
    "  OneLineTest = ${number},"
    "std::array<MutantName, ${number}> kMutantNames"
    "{Mutant::OneLineTest, \"one-line-test\", MutantKind::Shader,")
  set(cpp_check "static_assert(int(shaders::Mutant::OneLineTest) == ${number});
static_assert(shaders::kMutantNames.back().mutant == shaders::Mutant::OneLineTest);
static_assert(shaders::kMutantNames.back().name == \"one-line-test\");
static_assert(shaders::kMutantNames.back().kind == shaders::MutantKind::Shader);
")
  set(glsl_check "layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(MUTANT == MUTANT_ONE_LINE_TEST ? 1.0 : 0.0); }
")
elseif(KIND STREQUAL "texture")
  # Two samplers (oneLineTest0, oneLineTest1) in set 4 at bindings 5 and 6,
  # units 40 and 41, past every unit of the table.
  set(line "LIGHTCTS_TEXTURE(oneLineTest, 2, 4, 5, 40)")
  set(glsl_expected
    "#define LIGHTCTS_BINDING_oneLineTest0 set = 4, binding = 5"
    "#define LIGHTCTS_BINDING_oneLineTest1 set = 4, binding = 6")
  set(cpp_expected
    "kOneLineTestNames[] = {\"oneLineTest0\", \"oneLineTest1\"};"
    "Texture kOneLineTest{kOneLineTestNames, 4, 5, 40};"
    "kGlTextureUnitCount = 42;")
  set(cpp_check "static_assert(shaders::binding::kOneLineTest.count() == 2);
static_assert(shaders::binding::kOneLineTest.set == 4);
static_assert(shaders::binding::kOneLineTest.binding(1) == 6);
static_assert(shaders::binding::kOneLineTest.glUnit(1) == 41);
static_assert(std::string_view(shaders::binding::kOneLineTest.name(1)) == \"oneLineTest1\");
static_assert(shaders::binding::kGlTextureUnitCount == 42);
")
  set(glsl_check "layout(LIGHTCTS_BINDING(oneLineTest1)) uniform sampler2D oneLineTest1;
layout(location = 0) out vec4 outColor;
void main() { outColor = texture(oneLineTest1, vec2(0.5)); }
")
else()
  message(FATAL_ERROR "one_line_test.cmake: KIND is mutant or texture, not '${KIND}'")
endif()

# The one line.
file(WRITE "${table}" "${text}${line}\n")
execute_process(COMMAND "${CMAKE_COMMAND}" -DSHADER_INTERFACE_TABLE=${table}
                        -DSHADER_INTERFACE_GLSL=${WORK}/generated/glsl/shader_interface.glsl
                        -DSHADER_INTERFACE_HEADER=${WORK}/generated/shaders/shader_interface.h
                        -P "${SOURCE_DIR}/shaders/shader_interface.cmake"
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the generator refused the table with '${line}' appended:\n${output}")
endif()

file(READ "${WORK}/generated/glsl/shader_interface.glsl" glsl)
file(READ "${WORK}/generated/shaders/shader_interface.h" cpp)
foreach(expected IN LISTS glsl_expected)
  string(FIND "${glsl}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "generated/glsl/shader_interface.glsl lacks '${expected}' after '${line}':\n${glsl}")
  endif()
endforeach()
foreach(expected IN LISTS cpp_expected)
  string(FIND "${cpp}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "generated/shaders/shader_interface.h lacks '${expected}' after '${line}':\n${cpp}")
  endif()
endforeach()

# The C++ side compiles and holds the new values.
file(WRITE "${WORK}/check.cpp" "#include \"shaders/shader_interface.h\"\n\n#include <string_view>\n\n${cpp_check}")
execute_process(COMMAND "${CXX}" -std=c++20 -fsyntax-only -I${WORK}/generated -I${SOURCE_DIR} ${WORK}/check.cpp
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the generated C++ does not hold '${line}':\n${output}")
endif()

# The GLSL side compiles, and the sampler is where the table says.
file(WRITE "${WORK}/check.frag" "#version 450
#extension GL_GOOGLE_include_directive : require
#include \"shader_interface.glsl\"
${glsl_check}")
execute_process(COMMAND "${GLSLANG}" --quiet -V --target-env vulkan1.1 -I${WORK}/generated/glsl
                        -o ${WORK}/check.spv ${WORK}/check.frag
                RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the generated GLSL does not compile with '${line}':\n${output}")
endif()
if(KIND STREQUAL "texture")
  execute_process(COMMAND "${SPIRV_CROSS}" ${WORK}/check.spv --reflect
                  RESULT_VARIABLE status OUTPUT_VARIABLE reflected ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "spirv-cross --reflect failed:\n${output}")
  endif()
  string(JSON name GET "${reflected}" textures 0 name)
  string(JSON set GET "${reflected}" textures 0 set)
  string(JSON binding GET "${reflected}" textures 0 binding)
  if(NOT name STREQUAL "oneLineTest1" OR NOT set EQUAL 4 OR NOT binding EQUAL 6)
    message(FATAL_ERROR "the SPIR-V has ${name} at set ${set} binding ${binding}, not oneLineTest1 at set 4 binding 6")
  endif()
endif()
message(STATUS "'${line}' reached the GLSL and the C++")
