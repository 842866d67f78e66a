# Runs `lightcts compare` with one mutant on a short list of scenes, in order,
# and passes at the first scene that fails (exit 1): the comparison must be
# able to fail (SPEC 7, mutation check). Prints NotSupported (a ctest skip) when the
# backend is absent. Any other exit status (2, 4: a bad scene, a driver error,
# a validation message) fails the test: a mutant must be killed by the
# comparison, not by a crash. A kill needs its verdict only, so no evidence
# is written (`compare --no-evidence`); the evidence of a failure is the
# scene tests' and the run's to check.
#   cmake -DLIGHTCTS=exe -DBACKEND=vulkan [-DDRIVER=softpipe] -DMUTANT=name
#         -DSCENES=a.json,dir,... [-DSCENES_ROOT=dir] -P mutant_is_killed.cmake
# SCENES is a comma- or semicolon-separated list of scene files and folders
# (every *.json in a folder), relative to SCENES_ROOT when not absolute.
# SCENES_DIR (one folder) is still accepted.
set(entries)
if(DEFINED SCENES)
  string(REPLACE "," ";" entries "${SCENES}")
endif()
if(DEFINED SCENES_DIR)
  list(APPEND entries ${SCENES_DIR})
endif()
set(scenes)
foreach(entry ${entries})
  if(NOT IS_ABSOLUTE ${entry} AND DEFINED SCENES_ROOT)
    set(entry ${SCENES_ROOT}/${entry})
  endif()
  if(IS_DIRECTORY ${entry})
    file(GLOB folder_scenes ${entry}/*.json)
    list(SORT folder_scenes)
    list(APPEND scenes ${folder_scenes})
  elseif(EXISTS ${entry})
    list(APPEND scenes ${entry})
  else()
    message(FATAL_ERROR "mutant ${MUTANT}: no scene or folder ${entry}")
  endif()
endforeach()
if(NOT scenes)
  message(FATAL_ERROR "mutant ${MUTANT}: no scenes to run (SCENES='${SCENES}')")
endif()
set(driver_args)
if(DRIVER AND NOT DRIVER STREQUAL "default")
  set(driver_args --driver ${DRIVER})
endif()
set(killers "")
set(survivors "")
foreach(scene ${scenes})
  get_filename_component(name ${scene} NAME_WE)
  get_filename_component(group_dir ${scene} DIRECTORY)
  get_filename_component(group ${group_dir} NAME)
  execute_process(
    COMMAND ${LIGHTCTS} compare --scene ${scene} --backend ${BACKEND} ${driver_args} --mutant ${MUTANT} --no-evidence
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(status EQUAL 3)
    message("NotSupported: ${err}")
    return()
  elseif(status EQUAL 1)
    string(REGEX MATCH "[0-9]+ failing of [0-9]+" counts "${out}")
    list(APPEND killers "${group}/${name} (${counts})")
    break()  # killed: the later killers would only repeat it (`lightcts run` checks each)
  elseif(status EQUAL 0)
    list(APPEND survivors ${group}/${name})
  else()
    message(FATAL_ERROR "${group}/${name}: lightcts compare --mutant ${MUTANT} exited ${status}\n${out}${err}")
  endif()
endforeach()
if(NOT killers)
  message(FATAL_ERROR "mutant ${MUTANT} survived every scene (${survivors}) on ${BACKEND} ${DRIVER}: a scene is missing")
endif()
string(REPLACE ";" ", " killers "${killers}")
message("mutant ${MUTANT} killed on ${BACKEND} ${DRIVER} by: ${killers}")
if(survivors)
  string(REPLACE ";" ", " survivors "${survivors}")
  message("  (survived: ${survivors})")
endif()
