# What a build costs, decided here for every target once they are all
# defined (CMakeLists.txt calls lightcts_set_build_cost() last).
#
# Unity builds: every target's files are compiled together in batches of
# LIGHTCTS_UNITY_BATCH, so the headers most files include (the standard
# library, GLM, Vulkan-Hpp, nlohmann/json, GoogleTest) are parsed once per
# batch, not once per file. The product keeps the flags it ships with: a
# batch is the same code under the same flags. What a unity build needs of
# the code: no two files of one target define the same name at namespace
# scope, anonymous namespaces included (they are one namespace per batch).
# Targets that cannot be batched are listed in kept_per_file with why.
#
# Test programs (an executable that links GoogleTest) and every other target
# defined in a tests/ folder or in testing/ (the tests' own libraries and
# tools) are optimised with -O1: the code under test is the product's
# libraries, still -O3, and most of a test file's compile time is GCC's
# optimiser working on GoogleTest's macros and nlohmann/json's templates.
#
# LIGHTCTS_FAST_BUILD=OFF builds every target file by file, the tests like
# the product.
option(LIGHTCTS_FAST_BUILD "Unity builds, and test programs at -O1" ON)
set(LIGHTCTS_UNITY_BATCH 8 CACHE STRING "Files per unity batch")

# scene_input: gltf_import.cpp compiles tinygltf's implementation (its
# macros and stb_image's reach every file after it), and its files name two
# different JSON types Json.
set(kept_per_file scene_input)

function(lightcts_targets_below dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    lightcts_targets_below("${sub}" below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(lightcts_set_build_cost)
  if(NOT LIGHTCTS_FAST_BUILD)
    return()
  endif()
  lightcts_targets_below("${PROJECT_SOURCE_DIR}" targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
      continue()
    endif()
    if(NOT target IN_LIST kept_per_file)
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${LIGHTCTS_UNITY_BATCH})
    endif()
    get_target_property(libraries ${target} LINK_LIBRARIES)
    get_target_property(folder ${target} SOURCE_DIR)
    file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${folder}")
    if((type STREQUAL "EXECUTABLE" AND libraries MATCHES "GTest::") OR folder MATCHES "(^|/)tests$|^testing/")
      target_compile_options(${target} PRIVATE -O1)
    endif()
  endforeach()
endfunction()
