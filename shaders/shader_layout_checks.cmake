# The std140 layouts of the compiled shaders against the C++ structs the CPU
# fills them from. Reads the layouts SPIRV-Cross reflects from each stage's
# SPIR-V (REFLECTIONS: `spirv-cross <stage>.spv --reflect` outputs) and the
# shader interface's table (SHADER_INTERFACE_TABLE), and writes OUTPUT, a
# header of static_asserts that shaders/shader_layout_checks.cpp compiles:
# per member of every uniform block (and of every struct a member has), its
# offset, its C++ type (LIGHTCTS_TYPE) and, for an array, its length and
# stride; per block, its size. A member moved on one side only is a compile
# error naming the block and the member. Fails here, before any compiling,
# where the SPIR-V has a block, a texture or a member type the table does
# not describe, a binding other than the table's, or a table entry no stage
# uses. shaders/CMakeLists.txt runs it at build time:
#   cmake -DSHADER_INTERFACE_TABLE=... "-DREFLECTIONS=a.json;b.json" -DOUTPUT=... -P shader_layout_checks.cmake
cmake_policy(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/shader_interface_table.cmake)
si_require(shader_layout_checks.cmake REFLECTIONS OUTPUT)

# The indices of the JSON array at the path ARGN of `doc` (none where it is
# missing or empty).
function(json_indices out doc)
  string(JSON count ERROR_VARIABLE missing LENGTH "${doc}" ${ARGN})
  set(indices)
  if(NOT missing AND count GREATER 0)
    math(EXPR last "${count} - 1")
    foreach(i RANGE ${last})
      list(APPEND indices ${i})
    endforeach()
  endif()
  set(${out} ${indices} PARENT_SCOPE)
endfunction()

# Each member named in ARGN of the JSON object at `path` (a list) of `doc`,
# into the variable of its name.
function(json_fields doc path)
  foreach(field ${ARGN})
    string(JSON value GET "${doc}" ${path} ${field})
    set(${field} "${value}" PARENT_SCOPE)
  endforeach()
endfunction()

function(layout_fail stage message)
  message(FATAL_ERROR "${stage}: ${message} (shaders/shader_interface.def)")
endfunction()

# The static_asserts of GLSL struct or block `owner` (JSON type `type_id` of
# `doc`) against C++ type `cpp`, into the global property
# layout_checks_<owner>; the structs its members have are checked in turn.
# An owner met again must have the same layout (two stages, two blocks).
function(layout_check_type stage doc type_id owner cpp)
  set(text "// ${owner}: ${cpp}\n")
  json_indices(indices "${doc}" types ${type_id} members)
  foreach(m ${indices})
    string(JSON member GET "${doc}" types ${type_id} members ${m})
    string(JSON name GET "${member}" name)
    string(JSON type GET "${member}" type)
    string(JSON offset GET "${member}" offset)
    set(where "${owner}.${name}")
    set(cpp_member ${name})
    if(DEFINED si_member_${owner}_${name})
      set(cpp_member ${si_member_${owner}_${name}})
    endif()
    set(glsl_type ${type})
    if(type MATCHES "^_[0-9]+$")
      string(JSON glsl_type GET "${doc}" types ${type} name)
    endif()
    if(NOT DEFINED si_type_${glsl_type}_cpp)
      layout_fail(${stage} "${where} is a ${glsl_type}, a GLSL type with no LIGHTCTS_TYPE line")
    endif()
    set(cpp_type ${si_type_${glsl_type}_cpp})
    string(JSON row_major ERROR_VARIABLE no_row_major GET "${member}" row_major)
    string(JSON matrix_stride ERROR_VARIABLE no_matrix_stride GET "${member}" matrix_stride)
    if((NOT no_row_major AND row_major) OR (NOT no_matrix_stride AND NOT matrix_stride EQUAL 16))
      layout_fail(${stage} "${where} is a row-major matrix or one whose columns are not 16 bytes apart")
    endif()
    set(length 1)
    string(JSON array ERROR_VARIABLE no_array GET "${member}" array)
    if(NOT no_array)
      string(JSON dimensions LENGTH "${array}")
      if(NOT dimensions EQUAL 1)
        layout_fail(${stage} "${where} is an array of arrays")
      endif()
      string(JSON length GET "${array}" 0)
      string(JSON stride GET "${member}" array_stride)
    endif()
    set(decl "decltype(${cpp}::${cpp_member})")
    string(APPEND text
      "static_assert(offsetof(${cpp}, ${cpp_member}) == ${offset}, \"${where}: at offset ${offset} in the SPIR-V\");\n"
      "static_assert(std::is_same_v<Element<${decl}>, ${cpp_type}>, \"${where}: ${glsl_type} (${cpp_type}) in the SPIR-V\");\n"
      "static_assert(kLength<${decl}> == ${length}, \"${where}: ${length} element(s) in the SPIR-V\");\n")
    if(NOT no_array)
      string(APPEND text
        "static_assert(sizeof(Element<${decl}>) == ${stride}, \"${where}: elements ${stride} bytes apart in the SPIR-V\");\n")
    endif()
    if(type MATCHES "^_[0-9]+$")
      layout_check_type(${stage} "${doc}" ${type} ${glsl_type} ${cpp_type})
    endif()
  endforeach()
  get_property(seen GLOBAL PROPERTY layout_checks_${owner} SET)
  if(seen)
    get_property(before GLOBAL PROPERTY layout_checks_${owner})
    get_property(before_stage GLOBAL PROPERTY layout_stage_${owner})
    if(NOT before STREQUAL text)
      layout_fail(${stage} "${owner} is laid out otherwise than in ${before_stage}")
    endif()
  else()
    set_property(GLOBAL PROPERTY layout_checks_${owner} "${text}")
    set_property(GLOBAL PROPERTY layout_stage_${owner} ${stage})
    set_property(GLOBAL APPEND PROPERTY layout_owners ${owner})
  endif()
endfunction()

set(used)
foreach(reflection ${REFLECTIONS})
  get_filename_component(stage ${reflection} NAME_WE)
  file(READ ${reflection} doc)

  foreach(kind ssbos push_constants)
    json_indices(others "${doc}" ${kind})
    if(others)
      layout_fail(${stage} "has ${kind}, which the table does not describe")
    endif()
  endforeach()

  json_indices(indices "${doc}" ubos)
  foreach(i ${indices})
    json_fields("${doc}" "ubos;${i}" name type set binding block_size)
    set(block ${name})
    set(size ${block_size})
    if(NOT block IN_LIST si_blocks)
      layout_fail(${stage} "uniform block ${block} has no LIGHTCTS_UNIFORM_BLOCK line")
    endif()
    if(NOT set EQUAL si_block_${block}_set OR NOT binding EQUAL si_block_${block}_binding)
      layout_fail(${stage} "${block} is at set ${set} binding ${binding}, not at the table's: declare it with layout(std140, LIGHTCTS_BINDING(${block}))")
    endif()
    set(cpp ${si_block_${block}_cpp})
    layout_check_type(${stage} "${doc}" ${type} ${block} ${cpp})
    set_property(GLOBAL PROPERTY layout_size_${block}
      "static_assert(sizeof(${cpp}) == ${size}, \"${block}: ${size} bytes in the SPIR-V\");\n")
    list(APPEND used ${block})
  endforeach()

  json_indices(indices "${doc}" textures)
  foreach(i ${indices})
    json_fields("${doc}" "textures;${i}" name set binding)
    set(sampler ${name})
    set(row ${sampler})
    set(index 0)
    if(NOT sampler IN_LIST si_textures AND sampler MATCHES "^(.*[^0-9])([0-9]+)$")
      set(row ${CMAKE_MATCH_1})
      set(index ${CMAKE_MATCH_2})
      if(NOT row IN_LIST si_textures OR si_texture_${row}_count EQUAL 1 OR NOT index LESS si_texture_${row}_count)
        set(row ${sampler})
      endif()
    endif()
    if(NOT row IN_LIST si_textures)
      layout_fail(${stage} "sampler ${sampler} has no LIGHTCTS_TEXTURE line")
    endif()
    math(EXPR expected "${si_texture_${row}_binding} + ${index}")
    if(NOT set EQUAL si_texture_${row}_set OR NOT binding EQUAL expected)
      layout_fail(${stage} "${sampler} is at set ${set} binding ${binding}, not at the table's: declare it with layout(LIGHTCTS_BINDING(${sampler}))")
    endif()
    list(APPEND used ${row})
  endforeach()

  json_indices(indices "${doc}" specialization_constants)
  foreach(i ${indices})
    json_fields("${doc}" "specialization_constants;${i}" name id type)
    if(NOT id LESS si_constant_count OR NOT name STREQUAL si_constant_${id}_name OR NOT type STREQUAL si_constant_${id}_type)
      layout_fail(${stage} "specialization constant ${name} (${type}, id ${id}) is not the table's constant ${id}")
    endif()
  endforeach()
endforeach()

foreach(entry ${si_blocks} ${si_textures})
  if(NOT entry IN_LIST used)
    layout_fail("shader_layout_checks.cmake" "${entry} is in the table but in no shader stage")
  endif()
endforeach()

set(text "// Generated by shaders/shader_layout_checks.cmake from the layouts of the
// compiled SPIR-V (spirv-cross --reflect) and shaders/shader_interface.def:
// every member of every uniform block against the C++ struct the CPU fills.
#pragma once

#include <cstddef>
#include <type_traits>

namespace shaders::layout_checks {

template <class T>
using Element = std::remove_all_extents_t<T>;
template <class T>
inline constexpr std::size_t kLength = std::is_array_v<T> ? std::extent_v<T> : 1;

")
get_property(owners GLOBAL PROPERTY layout_owners)
foreach(owner ${owners})
  get_property(checks GLOBAL PROPERTY layout_checks_${owner})
  get_property(size GLOBAL PROPERTY layout_size_${owner})
  string(APPEND text "${checks}${size}\n")
endforeach()
string(APPEND text "}  // namespace shaders::layout_checks
")
# Written every time: the command's output is then newer than its inputs,
# so the build runs it again only when a stage or the table changes.
file(WRITE ${OUTPUT} "${text}")
