# Selection checks (SPEC 5, 5.4), included by scene_tests.cmake: the output of
# `lightcts lights` for every scene of the groups below against an expected
# selection written by hand in suite/selection/<group>/<name>.json, or
# <name>.frame-<f>.json for each frame of an animated scene (see
# suite/selection/README.md for how the answers were derived). Test names:
# <group>.<name>.selection, plus .frame-<f> per frame; labels "selection;<group>".
# A scene of these groups without its expected file gets a test that fails, so
# a new scene cannot go unchecked.
set(selection_groups limits per-object shadowmask)
set(selection_root ${CMAKE_CURRENT_SOURCE_DIR}/selection)
file(GLOB selection_expected_files CONFIGURE_DEPENDS ${selection_root}/*/*.json)
foreach(selection_group ${selection_groups})
  file(GLOB selection_scenes CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/scenes/${selection_group}/*.json)
  foreach(selection_scene ${selection_scenes})
    get_filename_component(selection_name ${selection_scene} NAME_WLE)
    # Frame count of the scene (1 when `frames` or `count` is absent); a
    # change to the scene reconfigures, so the per-frame tests follow it.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${selection_scene})
    file(READ ${selection_scene} selection_text)
    string(JSON selection_frames ERROR_VARIABLE selection_error GET "${selection_text}" frames count)
    if(selection_error)
      set(selection_frames 1)
    endif()
    set(selection_cases)
    if(selection_frames GREATER 1)
      math(EXPR selection_last "${selection_frames} - 1")
      foreach(selection_frame RANGE ${selection_last})
        list(APPEND selection_cases "${selection_frame}")
      endforeach()
    else()
      set(selection_cases "none")
    endif()
    foreach(selection_frame ${selection_cases})
      if(selection_frame STREQUAL "none")
        set(selection_test ${selection_group}.${selection_name}.selection)
        set(selection_file ${selection_root}/${selection_group}/${selection_name}.json)
        set(selection_frame_arg)
      else()
        set(selection_test ${selection_group}.${selection_name}.selection.frame-${selection_frame})
        set(selection_file ${selection_root}/${selection_group}/${selection_name}.frame-${selection_frame}.json)
        set(selection_frame_arg -DFRAME=${selection_frame})
      endif()
      if(EXISTS ${selection_file})
        add_test(NAME ${selection_test}
                 COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DSCENE=${selection_scene}
                         -DEXPECTED=${selection_file} ${selection_frame_arg}
                         -P ${CMAKE_CURRENT_SOURCE_DIR}/selection_matches.cmake)
      else()
        add_test(NAME ${selection_test}
                 COMMAND ${CMAKE_COMMAND} -DMISSING=${selection_scene} -DEXPECTED=${selection_file}
                         -P ${CMAKE_CURRENT_SOURCE_DIR}/selection_matches.cmake)
      endif()
      set_tests_properties(${selection_test} PROPERTIES LABELS "selection;${selection_group}")
    endforeach()
  endforeach()
endforeach()
