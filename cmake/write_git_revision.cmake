# Writes OUTPUT, a header defining LIGHTCTS_REVISION as `git describe
# --always --dirty` of SOURCE_DIR, or "unknown" when that fails (no git, not
# a git checkout, no commit yet). Leaves OUTPUT alone when it already says
# that, so its time stamp only moves when the revision does. Run at every
# build by git_revision.cmake:
#
#   cmake -DSOURCE_DIR=... -DOUTPUT=... [-DGIT=/usr/bin/git] -P write_git_revision.cmake
if(NOT SOURCE_DIR OR NOT OUTPUT)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=... -DOUTPUT=... [-DGIT=...] -P write_git_revision.cmake")
endif()

set(revision "unknown")
if(GIT)
  execute_process(COMMAND "${GIT}" describe --always --dirty
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  OUTPUT_VARIABLE described OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE status ERROR_QUIET)
  if(status EQUAL 0 AND NOT described STREQUAL "")
    set(revision "${described}")
  endif()
endif()

# A tag name may hold a double quote; a C string may not, unescaped.
string(REPLACE "\\" "\\\\" escaped "${revision}")
string(REPLACE "\"" "\\\"" escaped "${escaped}")
set(text "// Generated at build time by cmake/write_git_revision.cmake; do not edit.\n#pragma once\n#define LIGHTCTS_REVISION \"${escaped}\"\n")

if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
  if(old STREQUAL text)
    return()  # unchanged: keep the time stamp, recompile nothing
  endif()
endif()
file(WRITE "${OUTPUT}" "${text}")
