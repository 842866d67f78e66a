# The generated deferred variants (scenes/deferred/README.md): each original
# listed in scenes/deferred/variants.cmake, with a "pipeline" member that
# makes it deferred, its name prefixed with its group and its description
# prefixed with the sentence saying so. Written at configure time into
# scenes/deferred/ (where `lightcts run --scenes suite/scenes` finds them and
# scene_tests.cmake globs them; git ignores them), so an edit to an original
# reaches its variant on the next build.
#
# lightcts_write_deferred_variants(SCENES_DIR MANIFEST): configure time
#   (suite/CMakeLists.txt). MANIFEST, in the build folder, names the files it
#   wrote, so that the next run can remove those no longer listed.
# lightcts_check_deferred_variants(SCENES_DIR PROBLEMS_VAR): the files on disk
#   against their originals, for the test (check_deferred_variants.cmake).
# Both compare a variant with its original through _deferred_variant_problem:
# the writer checks each variant before it writes it.

# Sets ORIGINALS_VAR to the originals the list names, each pattern's matches
# sorted. Reads the list into the caller's scope (deferred_variant_*).
macro(_deferred_variants_load scenes_dir originals_var)
  include(${scenes_dir}/deferred/variants.cmake)
  set(${originals_var})
  foreach(_pattern IN LISTS deferred_variant_originals)
    if(_pattern MATCHES "[*?]")
      if(CMAKE_SCRIPT_MODE_FILE)
        file(GLOB _matched "${scenes_dir}/${_pattern}")
      else()
        # A new scene of a globbed group re-runs configure and gets its variant.
        file(GLOB _matched CONFIGURE_DEPENDS "${scenes_dir}/${_pattern}")
      endif()
      list(SORT _matched)
    else()
      set(_matched "${scenes_dir}/${_pattern}")
    endif()
    if(NOT _matched)
      message(FATAL_ERROR "${scenes_dir}/deferred/variants.cmake: no scene matches ${_pattern}")
    endif()
    list(APPEND ${originals_var} ${_matched})
  endforeach()
endmacro()

# Group, name and variant name of an original's path.
function(_deferred_variant_names original group_var name_var variant_var)
  get_filename_component(name "${original}" NAME_WLE)
  get_filename_component(group_dir "${original}" DIRECTORY)
  get_filename_component(group "${group_dir}" NAME)
  set(${group_var} "${group}" PARENT_SCOPE)
  set(${name_var} "${name}" PARENT_SCOPE)
  set(${variant_var} "${group}-${name}" PARENT_SCOPE)
endfunction()

# What the variant's description starts with (decoded text, not JSON).
function(_deferred_variant_description_prefix group name out_var)
  string(REPLACE "<BUFFER>" "${deferred_variant_buffer}" prefix "${deferred_variant_intro}")
  string(REPLACE "<ORIGINAL>" "${group}/${name}" prefix "${prefix}")
  string(APPEND prefix " ")
  if(DEFINED "deferred_variant_note_${group}-${name}")
    string(APPEND prefix "${deferred_variant_note_${group}-${name}} ")
  endif()
  set(${out_var} "${prefix}" PARENT_SCOPE)
endfunction()

# Sets OUT_VAR to "" when VARIANT (JSON text) is ORIGINAL (JSON text) with
# exactly the three changes, else to what is wrong. Compares parsed values,
# so layout and member order do not matter.
function(_deferred_variant_problem original variant group name out_var)
  set(problem "")
  string(JSON original_description ERROR_VARIABLE error GET "${original}" description)
  if(error)
    string(APPEND problem " the original has no description (${error});")
  endif()
  string(JSON ignored ERROR_VARIABLE error GET "${original}" pipeline)
  if(NOT error)
    string(APPEND problem " the original has a \"pipeline\" of its own, which its variant would replace;")
  endif()

  string(JSON variant_name ERROR_VARIABLE error GET "${variant}" name)
  if(error OR NOT variant_name STREQUAL "${group}-${name}")
    string(APPEND problem " its name is not \"${group}-${name}\";")
  endif()
  _deferred_variant_description_prefix("${group}" "${name}" prefix)
  string(JSON variant_description ERROR_VARIABLE error GET "${variant}" description)
  if(error OR NOT variant_description STREQUAL "${prefix}${original_description}")
    string(APPEND problem " its description is not the variant's sentence + the original's;")
  endif()
  string(JSON variant_pipeline ERROR_VARIABLE error GET "${variant}" pipeline)
  if(NOT error)
    string(JSON same ERROR_VARIABLE error EQUAL "${variant_pipeline}"
           "{\"path\": \"${deferred_variant_path}\", \"deferred_buffer\": \"${deferred_variant_buffer}\"}")
  endif()
  if(error OR NOT same)
    string(APPEND problem " its pipeline is not {path: ${deferred_variant_path}, deferred_buffer: ${deferred_variant_buffer}};")
  endif()

  # Everything else: equal once the three members are gone from both.
  set(variant_rest "${variant}")
  foreach(member pipeline name description)
    string(JSON variant_rest ERROR_VARIABLE error REMOVE "${variant_rest}" ${member})
  endforeach()
  set(original_rest "${original}")
  foreach(member name description)
    string(JSON original_rest ERROR_VARIABLE error REMOVE "${original_rest}" ${member})
  endforeach()
  string(JSON same ERROR_VARIABLE error EQUAL "${variant_rest}" "${original_rest}")
  if(error OR NOT same)
    string(APPEND problem " it differs from the original in more than name, description and pipeline;")
  endif()
  set(${out_var} "${problem}" PARENT_SCOPE)
endfunction()

# The position of NEEDLE in TEXT when it occurs exactly once, else fails.
function(_deferred_variant_find_once text needle what original out_var)
  string(FIND "${text}" "${needle}" first)
  string(FIND "${text}" "${needle}" last REVERSE)
  if(first EQUAL -1 OR NOT first EQUAL last)
    message(FATAL_ERROR "${original}: cannot make its deferred variant: no single top-level ${what} line. "
                        "Keep the layout of the other scenes (two-space indent, one member per line).")
  endif()
  set(${out_var} ${first} PARENT_SCOPE)
endfunction()

# The variant's text: the original's text with the name's value replaced,
# the sentence put in front of the description and a "pipeline" line put
# after the camera, so the file keeps the original's layout (string(JSON)
# would reorder the members and print 0.1 as 0.10000000000000001). Relies on
# what every scene's layout has: each top-level member starts a line with a
# two-space indent, and nothing deeper does; _deferred_variant_problem then
# checks the result as parsed JSON.
function(_deferred_variant_text original_file original group name variant out_var)
  set(text "${original}")

  set(key "\n  \"name\": \"")
  _deferred_variant_find_once("${text}" "${key}" "\"name\"" "${original_file}" at)
  string(LENGTH "${key}" key_length)
  math(EXPR value_at "${at} + ${key_length}")
  string(SUBSTRING "${text}" 0 ${value_at} head)
  string(SUBSTRING "${text}" ${value_at} -1 tail)
  string(FIND "${tail}" "\"" value_length)  # a scene name has no escaped quote
  string(SUBSTRING "${tail}" ${value_length} -1 tail)
  set(text "${head}${variant}${tail}")

  set(key "\n  \"description\": \"")
  _deferred_variant_find_once("${text}" "${key}" "\"description\"" "${original_file}" at)
  _deferred_variant_description_prefix("${group}" "${name}" prefix)
  string(REPLACE "\\" "\\\\" prefix "${prefix}")
  string(REPLACE "\"" "\\\"" prefix "${prefix}")
  string(REPLACE "${key}" "${key}${prefix}" text "${text}")

  # Before the top-level member that follows the camera; when the camera is
  # the last member, before the camera.
  set(pipeline "\n  \"pipeline\": {\n    \"path\": \"${deferred_variant_path}\",\n    \"deferred_buffer\": \"${deferred_variant_buffer}\"\n  },")
  set(key "\n  \"camera\": ")
  _deferred_variant_find_once("${text}" "${key}" "\"camera\"" "${original_file}" at)
  math(EXPR after_key "${at} + 1")
  string(SUBSTRING "${text}" ${after_key} -1 tail)
  string(FIND "${tail}" "\n  \"" next)
  if(NOT next EQUAL -1)
    math(EXPR at "${after_key} + ${next}")
  endif()
  string(SUBSTRING "${text}" 0 ${at} head)
  string(SUBSTRING "${text}" ${at} -1 tail)
  set(text "${head}${pipeline}${tail}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

function(lightcts_write_deferred_variants scenes_dir manifest)
  _deferred_variants_load("${scenes_dir}" originals)
  set(out_dir "${scenes_dir}/deferred")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
               ${originals} "${out_dir}/variants.cmake" "${CMAKE_CURRENT_FUNCTION_LIST_FILE}")
  # Two build folders may configure at once: their temporaries differ.
  string(MD5 writer "${CMAKE_BINARY_DIR}")
  set(written)
  foreach(original_file IN LISTS originals)
    _deferred_variant_names("${original_file}" group name variant)
    file(READ "${original_file}" original)
    string(JSON ignored ERROR_VARIABLE error TYPE "${original}")
    if(error)
      message(FATAL_ERROR "${original_file}: not JSON: ${error}")
    endif()
    _deferred_variant_text("${original_file}" "${original}" "${group}" "${name}" "${variant}" text)
    _deferred_variant_problem("${original}" "${text}" "${group}" "${name}" problem)
    if(problem)
      message(FATAL_ERROR "${original_file}: its generated deferred variant came out wrong:${problem}")
    endif()
    set(target "${out_dir}/${variant}.json")
    list(APPEND written "${variant}.json")
    if(EXISTS "${target}")
      file(READ "${target}" old)
      if(old STREQUAL text)
        continue()  # unchanged: keep the file and its time stamp
      endif()
    endif()
    # Written beside and renamed, so a run reading the scenes never sees half
    # a file; not *.json, so no scene glob takes the temporary.
    set(temporary "${out_dir}/.${variant}.${writer}.partial")
    file(WRITE "${temporary}" "${text}")
    file(RENAME "${temporary}" "${target}")
  endforeach()

  # A variant whose original left the list (or was renamed) goes too.
  if(EXISTS "${manifest}")
    file(STRINGS "${manifest}" previous)
    foreach(old IN LISTS previous)
      if(NOT old IN_LIST written)
        file(REMOVE "${out_dir}/${old}")
      endif()
    endforeach()
  endif()
  list(JOIN written "\n" lines)
  file(WRITE "${manifest}" "${lines}\n")
endfunction()

function(lightcts_check_deferred_variants scenes_dir problems_var)
  _deferred_variants_load("${scenes_dir}" originals)
  set(problems "")
  set(count 0)
  foreach(original_file IN LISTS originals)
    _deferred_variant_names("${original_file}" group name variant)
    set(variant_file "${scenes_dir}/deferred/${variant}.json")
    if(NOT EXISTS "${variant_file}")
      string(APPEND problems "${variant_file}: missing (configure writes it)\n")
      continue()
    endif()
    file(READ "${original_file}" original)
    file(READ "${variant_file}" variant_text)
    _deferred_variant_problem("${original}" "${variant_text}" "${group}" "${name}" problem)
    if(problem)
      string(APPEND problems "${variant_file}:${problem} (is it stale? build again)\n")
    endif()
    math(EXPR count "${count} + 1")
  endforeach()
  set(${problems_var} "${problems}" PARENT_SCOPE)
  set(${problems_var}_COUNT ${count} PARENT_SCOPE)
endfunction()
