# lightcts_embedded_text_header(TARGET HEADER NAMESPACE CONSTANT FILE): a
# header (under TARGET's binary folder, generated/HEADER) holding FILE's text
# as `inline constexpr std::string_view NAMESPACE::CONSTANT`, remade at
# configure time whenever FILE changes. The binary then carries the file
# (the evidence viewer's page), so it never reads the source tree at run time.
function(lightcts_embedded_text_header target header namespace constant file)
  set_property(DIRECTORY ${CMAKE_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${file})
  file(READ ${file} embedded_text)
  if(embedded_text MATCHES "\\)lightcts_text\"")
    message(FATAL_ERROR "${file} holds the raw-string delimiter )lightcts_text\"")
  endif()
  set(output ${CMAKE_CURRENT_BINARY_DIR}/generated/${header})
  # @ONLY and the text in a variable: nothing inside the file is substituted.
  file(CONFIGURE OUTPUT ${output} CONTENT
"// Generated from ${file} by cmake/embedded_text_header.cmake: do not edit.
#pragma once
#include <string_view>
namespace ${namespace} {
inline constexpr std::string_view ${constant} = R\"lightcts_text(@embedded_text@)lightcts_text\";
}
" @ONLY)
  target_include_directories(${target} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
endfunction()
