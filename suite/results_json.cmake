# The one way the suite's CMake scripts read a lightcts results.json
# (docs/results-format.md, "Reading a results.json"), as lightcts's own
# reader (results/results_file.h) and suite/results_json.py do: a file that is
# not a results.json, or whose "tests" or "backends" is missing or no array,
# stops the script with a message naming the file and the key. (Each
# record's keys are the readers' to check: string(JSON) parses the whole text
# again for every query, too slow for a loop over a run's tests.)
function(lightcts_read_results file out_var)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file}: cannot be read")
  endif()
  file(READ "${file}" text)
  string(JSON format ERROR_VARIABLE error GET "${text}" format)
  if(error OR NOT format STREQUAL "lightcts-results")
    message(FATAL_ERROR "${file}: not a lightcts results.json (no \"format\": \"lightcts-results\")")
  endif()
  foreach(array tests backends)
    string(JSON type ERROR_VARIABLE error TYPE "${text}" ${array})
    if(error)
      message(FATAL_ERROR "${file}: ${array} is missing")
    elseif(NOT type STREQUAL "ARRAY")
      message(FATAL_ERROR "${file}: ${array} is not an array")
    endif()
  endforeach()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()
