# Choosing tests by name (SPEC 8; docs/cli.md "Selection"): --include,
# --exclude and --caselist through the real binary. Included by
# scene_tests.cmake, which defines backend_test_environment.
set(choice_out ${CMAKE_BINARY_DIR}/test-out/test-choice)
set(choice_scenes ${CMAKE_CURRENT_SOURCE_DIR}/scenes)

function(add_choice_test name group suffixes args)
  add_test(NAME run.choice-${name}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DSCENES=${choice_scenes} -DGROUP=${group}
                   "-DSUFFIXES=${suffixes}" "-DARGS=${args}" -P ${CMAKE_CURRENT_SOURCE_DIR}/test_choice_outcome.cmake)
  set_tests_properties(run.choice-${name} PROPERTIES LABELS "run;choice")
endfunction()

# The shadows tests of the four Mesa combinations that are not softpipe,
# by globs and by a caselist (with comments and a blank line) that lists them.
add_choice_test(include-and-exclude shadows "vulkan;gl-egl;gl-osmesa;gl-egl-zink"
  "--include;shadows.*;--exclude;*softpipe*;--exclude;*swiftshader*")
set(shadows_caselist ${CMAKE_CURRENT_BINARY_DIR}/shadows-caselist.txt)
file(WRITE ${shadows_caselist}
  "# the shadows group, softpipe left out (written by suite/test_choice_tests.cmake)\n\n"
  "shadows.*.vulkan\nshadows.*.gl-egl   # llvmpipe through EGL\nshadows.*.gl-osmesa\n"
  "shadows.*.gl-egl-zink   # zink on lavapipe\n")
add_choice_test(caselist-does-the-same shadows "vulkan;gl-egl;gl-osmesa;gl-egl-zink" "--caselist;${shadows_caselist}")
# --driver turns the GL combinations into those of the driver named.
add_choice_test(driver-names-the-gl-combinations limits "gl-egl-softpipe;gl-osmesa-softpipe"
  "--backend;gl-egl;--backend;gl-osmesa;--driver;softpipe;--include;limits.*")

# --list is a caselist, and the shards of a selection partition it.
add_test(NAME run.choice-list-is-a-caselist-and-shards-partition-it
         COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DSCENES=${choice_scenes}
                 -DOUT=${choice_out}/lists "-DARGS=--include;shadows.*;--include;limits.*;--exclude;*osmesa*"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/test_choice_lists.cmake)
set_tests_properties(run.choice-list-is-a-caselist-and-shards-partition-it PROPERTIES LABELS "run;choice")

# A glob or a caselist line that matches nothing is bad input (exit 2),
# named with its file and line; nothing is written.
set(typo_caselist ${CMAKE_CURRENT_BINARY_DIR}/typo-caselist.txt)
file(WRITE ${typo_caselist} "# one good line, then a typo\nshadows.*.vulkan\nshadow.acne-no-bias.vulkan\n")
foreach(case "include-matching-nothing-exits-2|--include;shadow.*|--include: 'shadow\\.\\*' matches no test"
              "caselist-line-matching-nothing-exits-2|--caselist;${typo_caselist}|typo-caselist.txt:3: 'shadow.acne-no-bias.vulkan' matches no test"
              "selection-leaving-nothing-exits-2|--include;shadows.*;--exclude;shadows.*|leaves no test"
              "unreadable-caselist-exits-2|--caselist;/nonexistent/caselist.txt|cannot read /nonexistent/caselist.txt"
              "mutant-without-a-selected-killer-exits-2|--include;limits.*;--mutant;shadow-fade-ignored|--mutant shadow-fade-ignored: none of its killers \\(shadows.fade-across-shadow-distance\\)"
              "mutants-only-without-a-killer-exits-2|--include;limits.*;--mutants-only|the selection holds no killer"
              "driver-against-a-named-driver-exits-2|--backend;gl-egl-softpipe;--driver;llvmpipe|--backend gl-egl-softpipe runs softpipe"
              "all-scenes-without-mutants-exits-2|--mutants-all-scenes;--no-mutants|choose one")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts -1 regex)
  list(REMOVE_AT parts 0 -1)
  add_test(NAME run.choice-${name}
           COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DOUT=${choice_out}/${name} -DEXIT=2
                   "-DARGS=--scenes;${choice_scenes};${parts}" "-DOUTPUT_REGEX=${regex}"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/run_outcome.cmake)
  set_tests_properties(run.choice-${name} PROPERTIES LABELS "run;choice")
endforeach()

# A real run of a selection: results.json holds exactly the selected tests,
# the selection as given, and each caselist and baseline with its SHA-256
# (suite/check_test_choice.py computes the digests itself).
set(point_caselist ${CMAKE_CURRENT_BINARY_DIR}/point-caselist.txt)
file(WRITE ${point_caselist} "attenuation.point-d-*.vulkan  # the point lights at d = 0 .. r\n")
set(point_baseline ${CMAKE_CURRENT_BINARY_DIR}/point-baseline.txt)
file(WRITE ${point_baseline} "# nothing expected to fail, listed only to be recorded\n")
add_test(NAME run.choice-real-run-records-its-selection
         COMMAND ${CMAKE_COMMAND} -E env ${backend_test_environment}
                 ${LIGHTCTS_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/check_test_choice.py $<TARGET_FILE:lightcts>
                 ${choice_out}/real-run ${choice_scenes}/attenuation ${point_caselist} ${point_baseline})
set_tests_properties(run.choice-real-run-records-its-selection PROPERTIES LABELS "run;choice;vulkan"
  SKIP_RETURN_CODE 77)
