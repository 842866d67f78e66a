# add_source_fingerprint_header(TARGET HEADER NAMESPACE CONSTANT COMMENT SOURCES...):
# a header (under TARGET's binary folder, generated/HEADER) with one SHA-256
# over SOURCES as NAMESPACE::CONSTANT, made at build time by
# baking/source_fingerprint.cmake and remade whenever a source changes. The
# bake cache, the reference cache and the bench's kept errors key by one each,
# so a change in their code never meets a stale file.
function(add_source_fingerprint_header target header namespace constant comment)
  set(output ${CMAKE_CURRENT_BINARY_DIR}/generated/${header})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} "-DSOURCES=${ARGN}" -DNAMESPACE=${namespace} -DCONSTANT=${constant}
            -P ${PROJECT_SOURCE_DIR}/baking/source_fingerprint.cmake
    DEPENDS ${ARGN} ${PROJECT_SOURCE_DIR}/baking/source_fingerprint.cmake
    COMMENT "${comment}"
    VERBATIM)
  target_sources(${target} PRIVATE ${output})
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
endfunction()
