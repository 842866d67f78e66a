# glTF import (SPEC 2.1), label `gltf` (the scenes of suite/scenes/gltf/ carry
# it too, as their group): the built-ins written as glTF give the built-ins'
# images bit for bit, the package's real and broken files, the fuzzed files,
# and the generated models are what the generator writes.
set(gltf_dir ${CMAKE_CURRENT_SOURCE_DIR}/gltf)
set(gltf_scenes ${CMAKE_CURRENT_SOURCE_DIR}/scenes/gltf)
set(gltf_out ${CMAKE_BINARY_DIR}/test-out/gltf)

# The plane, sphere and box written as glTF (suite/gltf/generate_models.py),
# imported, against the same built-in meshes: each backend's image and the
# reference's value and tolerance, every bit.
foreach(shape plane sphere box)
  set(builtin ${gltf_scenes}/builtin-${shape}.json)
  set(imported ${gltf_scenes}/${shape}-as-gltf.json)
  set(test gltf.${shape}-as-gltf-is-the-builtin.reference)
  set(out ${gltf_out}/${test})
  add_test(NAME ${test}
           COMMAND sh -c "$<TARGET_FILE:lightcts> reference --scene ${builtin} --out ${out}/builtin && \
$<TARGET_FILE:lightcts> reference --scene ${imported} --out ${out}/imported && \
${LIGHTCTS_PYTHON3} ${gltf_dir}/check_same_images.py ${out}/builtin/reference.exr ${out}/imported/reference.exr \
${out}/builtin/tolerance.exr ${out}/imported/tolerance.exr")
  set_tests_properties(${test} PROPERTIES LABELS "gltf;reference"
    ENVIRONMENT "LIGHTCTS_CACHE_DIR=${CMAKE_BINARY_DIR}/cache")
  foreach(combination ${backend_combinations})
    split_combination(${combination})
    set(test gltf.${shape}-as-gltf-is-the-builtin.${suffix})
    set(out ${gltf_out}/${test})
    string(REPLACE ";" " " driver_text "${driver_args}")
    # Exit 3 (no such device or driver) from either render is a skip.
    add_test(NAME ${test}
             COMMAND sh -c "mkdir -p ${out} && \
$<TARGET_FILE:lightcts> render --scene ${builtin} --backend ${backend} ${driver_text} --out ${out}/builtin.exr || exit $?; \
$<TARGET_FILE:lightcts> render --scene ${imported} --backend ${backend} ${driver_text} --out ${out}/imported.exr || exit $?; \
${LIGHTCTS_PYTHON3} ${gltf_dir}/check_same_images.py ${out}/builtin.exr ${out}/imported.exr")
    set_tests_properties(${test} PROPERTIES LABELS "gltf;${suffix}" SKIP_RETURN_CODE 3 TIMEOUT 300
      ENVIRONMENT "${backend_test_environment}" FAIL_REGULAR_EXPRESSION "Validation (Error|Warning)|VUID-")
  endforeach()
endforeach()

# The checked-in models are exactly what the generator writes.
add_test(NAME gltf.generated-models-are-current
         COMMAND sh -c "rm -rf ${gltf_out}/generated && \
${LIGHTCTS_PYTHON3} ${gltf_dir}/generate_models.py --out ${gltf_out}/generated && \
diff -r ${gltf_out}/generated ${gltf_scenes}/models")
set_tests_properties(gltf.generated-models-are-current PROPERTIES LABELS "gltf;unit")

# Every glTF file of Debian's assimp-testmodels: the real ones load, the
# broken ones exit 2 naming the file and the JSON path (exit 3: the package
# is missing, a skip).
add_test(NAME gltf.package-files-load-or-are-refused-with-their-path
         COMMAND ${LIGHTCTS_PYTHON3} ${gltf_dir}/check_package_files.py $<TARGET_FILE:lightcts>)
set_tests_properties(gltf.package-files-load-or-are-refused-with-their-path PROPERTIES
  LABELS "gltf;cli" SKIP_RETURN_CODE 3 TIMEOUT 600)

# 150 broken files made from the generated ones: exit 0, 2 or 3 only. 150
# draws about 200 mutations from the 25 kinds (each kind is missed with
# probability (24/25)^200, 3e-4); `fuzz_gltf.py --count 1000` by hand goes
# further (each lightcts process costs about half a second to start).
add_test(NAME gltf.fuzzed-files-exit-0-2-or-3
         COMMAND sh -c "rm -rf ${gltf_out}/fuzz && ${LIGHTCTS_PYTHON3} ${gltf_dir}/fuzz_gltf.py \
--lightcts $<TARGET_FILE:lightcts> --seeds ${gltf_scenes}/models --out ${gltf_out}/fuzz --count 150 --seed 1 --jobs 2")
set_tests_properties(gltf.fuzzed-files-exit-0-2-or-3 PROPERTIES LABELS "gltf;cli" TIMEOUT 900
  ENVIRONMENT "LIGHTCTS_CACHE_DIR=${CMAKE_BINARY_DIR}/cache")

# A glTF file without lights (the generated box) is lit by the default rig
# (docs/scene-format.md): its comparison is a real Pass, not a black frame's
# QualityWarning; and the scene `lights --scene-json` prints for it, saved
# and loaded as a scene file, passes the same way.
add_test(NAME gltf.bare-file-without-lights-is-lit-by-the-rig
         COMMAND lightcts compare --scene ${gltf_scenes}/models/box.gltf --backend vulkan --no-evidence)
add_test(NAME gltf.printed-rig-scene-loads-and-passes
         COMMAND sh -c "mkdir -p ${gltf_out} && \
$<TARGET_FILE:lightcts> lights --scene ${gltf_scenes}/models/box.gltf --scene-json > ${gltf_out}/box-rig.json && \
$<TARGET_FILE:lightcts> compare --scene ${gltf_out}/box-rig.json --backend vulkan --no-evidence")
set_tests_properties(gltf.bare-file-without-lights-is-lit-by-the-rig gltf.printed-rig-scene-loads-and-passes
  PROPERTIES LABELS "gltf;vulkan" SKIP_RETURN_CODE 3 ENVIRONMENT "${backend_test_environment}"
  PASS_REGULAR_EXPRESSION "(^|\n)Pass [^\n]*: 0 failing" FAIL_REGULAR_EXPRESSION "QualityWarning")
