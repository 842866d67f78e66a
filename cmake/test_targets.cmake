# How the test programs are built. The product (the lightcts libraries, the
# command, the bench) keeps the Release flags it ships with; a test program
# is compiled to check behaviour, and most of its compile time is GCC's
# optimiser working on GoogleTest's macros and nlohmann/json's templates.
# So each test program (an executable that links GoogleTest) is
#   - optimised with -O1: the code under test is the product's libraries,
#     still -O3, and the tests' own loops stay fast enough for their budget;
#   - a unity build: its files compiled together in batches, so the
#     GoogleTest and JSON headers are parsed once per batch, not per file
#     (so two test files of one program never define the same helper);
# and every other target defined in a tests/ folder or in testing/ (the
# tests' own libraries and tools) is optimised with -O1 too.
# LIGHTCTS_FAST_TEST_BUILD=OFF builds them like the product instead.
option(LIGHTCTS_FAST_TEST_BUILD "Build test programs at -O1 as unity builds" ON)
set(LIGHTCTS_TEST_UNITY_BATCH 8 CACHE STRING "Files per unity batch of a test program")

function(lightcts_targets_below dir out)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    lightcts_targets_below("${sub}" below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(lightcts_build_test_programs_fast)
  if(NOT LIGHTCTS_FAST_TEST_BUILD)
    return()
  endif()
  lightcts_targets_below("${PROJECT_SOURCE_DIR}" targets)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    get_target_property(libraries ${target} LINK_LIBRARIES)
    get_target_property(folder ${target} SOURCE_DIR)
    file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${folder}")
    if(type STREQUAL "EXECUTABLE" AND libraries MATCHES "GTest::")
      target_compile_options(${target} PRIVATE -O1)
      set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${LIGHTCTS_TEST_UNITY_BATCH})
    elseif(folder MATCHES "(^|/)tests$|^testing/" AND type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY)$")
      target_compile_options(${target} PRIVATE -O1)
    endif()
  endforeach()
endfunction()
