# A validation-layer message that no draw threw (said at start-up or
# shutdown) is only in the workers' logs of a `lightcts run`: included by the
# scripts that run one (scene_run.cmake, admissible_run.cmake), this fails
# the script on any such line under `logs_dir`.
function(fail_on_validation_messages logs_dir)
  file(GLOB worker_logs ${logs_dir}/*.log)
  foreach(worker_log ${worker_logs})
    file(STRINGS ${worker_log} layer_lines REGEX "Validation (Error|Warning)|VUID-")
    if(layer_lines)
      string(REPLACE ";" "\n" layer_lines "${layer_lines}")
      message(FATAL_ERROR "validation-layer messages in ${worker_log}:\n${layer_lines}")
    endif()
  endforeach()
endfunction()
