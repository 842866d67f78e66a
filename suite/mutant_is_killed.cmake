# Runs `lightcts compare` with one mutant on every scene of a folder and
# passes only when at least one scene fails (exit 1): the comparison must be
# able to fail (SPEC 7, mutation check). Prints NotSupported (a ctest skip)
# when the backend is absent.
#   cmake -DLIGHTCTS=exe -DBACKEND=vulkan [-DDRIVER=softpipe] -DMUTANT=name -DSCENES_DIR=dir
#         -DEVIDENCE_DIR=dir -P mutant_is_killed.cmake
file(GLOB scenes ${SCENES_DIR}/*.json)
set(driver_args)
if(DRIVER AND NOT DRIVER STREQUAL "default")
  set(driver_args --driver ${DRIVER})
endif()
set(killers "")
foreach(scene ${scenes})
  get_filename_component(name ${scene} NAME_WE)
  execute_process(
    COMMAND ${LIGHTCTS} compare --scene ${scene} --backend ${BACKEND} ${driver_args} --mutant ${MUTANT}
            --evidence ${EVIDENCE_DIR}/${name}
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(status EQUAL 3)
    message("NotSupported: ${err}")
    return()
  elseif(status EQUAL 1)
    list(APPEND killers ${name})
  elseif(NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: lightcts compare exited ${status}\n${out}${err}")
  endif()
endforeach()
if(NOT killers)
  message(FATAL_ERROR "mutant ${MUTANT} survived every scene of ${SCENES_DIR} on ${BACKEND}: a scene is missing")
endif()
message("mutant ${MUTANT} killed on ${BACKEND} by: ${killers}")
