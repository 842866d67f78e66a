# junit.xml of a real run with a failure that has evidence: it validates
# against the JUnit schema (CHECK: reports/tests/check_junit_schema.sh; its
# exit 77, no xmllint, is passed on as a skip) and the failing testcase names
# PAGE, its evidence page, in its message and its details.
#   cmake -DJUNIT=junit.xml -DCHECK=check_junit_schema.sh -DPAGE=url -P junit_names_evidence.cmake
execute_process(COMMAND ${CHECK} ${JUNIT} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(status EQUAL 77)
  cmake_language(EXIT 77)
endif()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${JUNIT} does not validate against the schema")
endif()
file(READ ${JUNIT} junit)
string(FIND "${junit}" "(evidence: ${PAGE})\"" in_message)
string(FIND "${junit}" ">evidence: ${PAGE}\n" in_details)
if(in_message EQUAL -1 OR in_details EQUAL -1)
  message(FATAL_ERROR "${JUNIT} does not name ${PAGE} in the failure's message and details:\n${junit}")
endif()
message("validates, and the failure names ${PAGE}")
