# The revision in results.json is taken at build time (cmake/git_revision.cmake):
# a throwaway project that uses the same function, built with this build's
# generator, in a throwaway repository. Outside a git checkout it says
# "unknown"; after `git init` and a commit, a plain rebuild (no re-configure)
# says that commit; a rebuild with nothing new rewrites nothing; a second
# commit, again with no re-configure, changes it; an edit adds "-dirty".
# A configure-time `git describe` would stay "unknown" after the first
# commit and fail at that step.
#
#   cmake -DMODULE=<cmake/git_revision.cmake> -DWORK=<scratch folder> [-DGENERATOR=Ninja]
#         -P git_revision_test.cmake
if(NOT MODULE OR NOT WORK)
  message(FATAL_ERROR "usage: cmake -DMODULE=... -DWORK=... [-DGENERATOR=...] -P git_revision_test.cmake")
endif()
find_program(GIT git REQUIRED)

set(repo "${WORK}/repo")
set(build "${WORK}/build")
set(header "${build}/generated/git_revision.h")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${repo}")

# Git sees only the throwaway repository (never the checkout around the build
# folder) and no user's configuration.
set(ENV{GIT_CEILING_DIRECTORIES} "${WORK}")
set(ENV{GIT_CONFIG_NOSYSTEM} 1)
set(ENV{GIT_CONFIG_GLOBAL} /dev/null)
foreach(who AUTHOR COMMITTER)
  set(ENV{GIT_${who}_NAME} "lightcts test")
  set(ENV{GIT_${who}_EMAIL} "test@lightcts.invalid")
endforeach()

file(WRITE "${repo}/CMakeLists.txt" "cmake_minimum_required(VERSION 3.25)
project(revision_probe LANGUAGES CXX)
include(\"${MODULE}\")
add_executable(probe probe.cpp)
lightcts_git_revision_header(probe_revision probe \${CMAKE_BINARY_DIR}/generated/git_revision.h)
target_include_directories(probe PRIVATE \${CMAKE_BINARY_DIR}/generated)
")
file(WRITE "${repo}/probe.cpp" "#include \"git_revision.h\"\n#include <cstdio>\nint main() { std::puts(LIGHTCTS_REVISION); }\n")
file(WRITE "${repo}/notes.txt" "one\n")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${output}")
  endif()
endfunction()
function(git)
  run("${GIT}" -C "${repo}" ${ARGN})
endfunction()
# Builds (never configures) and sets `var` to what the program prints.
function(built_revision var)
  run("${CMAKE_COMMAND}" --build "${build}")
  execute_process(COMMAND "${build}/probe" OUTPUT_VARIABLE printed OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "the probe failed (${status})")
  endif()
  set(${var} "${printed}" PARENT_SCOPE)
endfunction()
function(expect what actual expected)
  if(NOT actual STREQUAL expected)
    message(FATAL_ERROR "${what}: the build says \"${actual}\", expected \"${expected}\"")
  endif()
  message(STATUS "${what}: ${actual}")
endfunction()
function(short_head var)
  execute_process(COMMAND "${GIT}" -C "${repo}" rev-parse --short HEAD OUTPUT_VARIABLE head
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(${var} "${head}" PARENT_SCOPE)
endfunction()

# Configured once, outside any git checkout.
set(generator)
if(GENERATOR)
  set(generator -G "${GENERATOR}")
endif()
run("${CMAKE_COMMAND}" -S "${repo}" -B "${build}" ${generator})
built_revision(revision)
expect("outside a git checkout" "${revision}" "unknown")

git(init -q)
git(add -A)
git(commit -q -m one)
short_head(first)
built_revision(revision)
expect("after the first commit, no re-configure" "${revision}" "${first}")

# Nothing new: the header keeps its (here, made-up old) time stamp.
run(touch -d @946684800 "${header}")
built_revision(revision)
expect("a rebuild with nothing new" "${revision}" "${first}")
file(TIMESTAMP "${header}" stamp "%s" UTC)
if(NOT stamp STREQUAL "946684800")
  message(FATAL_ERROR "a rebuild with no new revision rewrote ${header}")
endif()

file(APPEND "${repo}/notes.txt" "two\n")
git(commit -q -a -m two)
short_head(second)
if(second STREQUAL first)
  message(FATAL_ERROR "two commits with one short hash")
endif()
built_revision(revision)
expect("after a second commit, no re-configure" "${revision}" "${second}")

file(APPEND "${repo}/notes.txt" "three\n")
built_revision(revision)
expect("with an uncommitted edit" "${revision}" "${second}-dirty")
