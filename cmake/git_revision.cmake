# The git revision of the sources as a generated header, taken at every
# build, not at configure time: a commit (or an edit that makes the tree
# dirty) without a re-configure reaches the next build's results.json.
#
# lightcts_git_revision_header(TARGET CONSUMER HEADER): adds the custom target
#   TARGET, which runs write_git_revision.cmake on every build of CONSUMER
#   (before CONSUMER compiles) and writes HEADER, defining LIGHTCTS_REVISION
#   as `git describe --always --dirty` of PROJECT_SOURCE_DIR, or "unknown"
#   outside a git checkout. HEADER is rewritten only when the revision
#   changed, so a build with no new revision recompiles nothing.
#   cmake/tests/git_revision_test.cmake tests it in a throwaway repository.
set(_lightcts_write_git_revision ${CMAKE_CURRENT_LIST_DIR}/write_git_revision.cmake)

function(lightcts_git_revision_header target consumer header)
  find_package(Git QUIET)  # none: the revision is "unknown"
  add_custom_target(${target}
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT=${header}
            -DGIT=${GIT_EXECUTABLE} -P ${_lightcts_write_git_revision}
    BYPRODUCTS ${header}  # Ninja re-checks its time stamp: unchanged, nothing recompiles
    COMMENT "git revision of the sources"
    VERBATIM)
  add_dependencies(${consumer} ${target})
endfunction()
