# Mutant tests (SPEC 7, mutation check); included by scene_tests.cmake,
# which defines backend_combinations, split_combination and backend_test_environment.
#
# Every deliberately wrong variant of the model (shaders::mutantNames(),
# shaders/mutants.glsl) must make at least one scene fail, on every backend and
# driver: mutants.<mutant>.<backend-suffix>, labels "mutants;<suffix>". A
# process costs ~0.3 s per compare, so each mutant runs only the scenes meant
# to kill it: "<mutant>=<scene or folder>,<scene or folder>,...", relative to
# suite/scenes. (`lightcts run` runs every mutant over every scene and writes
# the whole kill table.)
set(mutant_killers
  "distance-clamp-1e-4=attenuation/point-5mm-above-floor.json,attenuation/point-3mm-above-floor-close-up.json"
  "unsquared-range=attenuation/point-d-0p8-range.json"
  "unsquared-spot=attenuation/spot-inner-outer-edges.json"
  "full-spot-angle=attenuation/spot-inner-outer-edges.json"
  "unsanitised-object-loop=per-object/eleven-lights.json,per-object/importance-ties.json"
  "half-precision-attenuation=attenuation/point-attenuation-below-half-range.json,attenuation/point-3mm-above-floor-close-up.json"
  "absolute-coordinates=stability/translated-1e5.json,stability/translated-1e6.json"
  "vertex-normal-not-normalised=legacy/scaled-object.json"
  "directional-not-saturated=attenuation/directional-grazing.json"
  "spot-direction-flipped=attenuation/spot-inner-outer-edges.json"
  "local-not-saturated=legacy/four-pixel-four-vertex.json,attenuation/point-d-zero.json"
  "legacy-vertex-lights-dropped=legacy/four-pixel-four-vertex.json"
  "shadow-mask-channel-off-by-one=shadowmask/four-overlapping-mixed.json,shadowmask/far-apart-share-channel.json"
  "shadow-strength-ignored=shadowmask/strength-0-half-1.json"
  "demoted-light-still-lit=shadowmask/fifth-overlapping-demoted.json"
  "legacy-falloff-baked=baked/spot-directional-no-range.json,baked/shadows-box-on-plane.json"
  "unclamped-ldr-decode=deferred/ldr8-sums.json"
  "point-volume-outside-only=deferred/camera-inside-point-volume.json,deferred/camera-inside-wide-spot-volume.json"
  "d2-without-epsilon=brdf/smoothness-1.json,brdf/point-1cm-above.json"
  "lh2-not-clamped=brdf/grazing-view.json,brdf/light-opposite-view.json"
  "f0-albedo-always=brdf/metallic-0.json"
  "view-absolute-coordinates=brdf/translated-1e5.json"
  "half-vector-not-normalised=brdf/smoothness-0p9.json"
  "directional-cookie-clamped=cookies/directional-tiled-many-repeats.json"
  "cube-cookie-rotated-90=cookies/point-cube-seams-corner.json"
  "cookie-v-flipped=cookies/directional-tiled-many-repeats.json,cookies/alpha-channel.json,cookies/spot-cone-crosses-light-plane.json"
  "shadow-compare-less=shadows/far-face-equal-depth.json"
  "shadow-depth-bias-ignored=shadows/acne-sufficient-bias.json"
  "shadow-normal-bias-along-l=shadows/normal-bias-sloped-receiver.json"
  "shadow-texel-centres-shifted=shadows/hard-texel-steps-close-up.json"
  "shadow-fade-ignored=shadows/fade-across-shadow-distance.json"
  "cube-shadow-wrong-axis=shadows/point-cube-faces.json"
  "shadow-strength-as-power=shadows/strengths-0-half-1.json")
foreach(entry ${mutant_killers})
  string(REPLACE "=" ";" mutant_parts ${entry})
  list(GET mutant_parts 0 mutant)
  list(GET mutant_parts 1 mutant_scenes)
  foreach(combination ${backend_combinations})
    split_combination(${combination})
    add_test(NAME mutants.${mutant}.${suffix}
             COMMAND ${CMAKE_COMMAND} -DLIGHTCTS=$<TARGET_FILE:lightcts> -DBACKEND=${backend} -DDRIVER=${driver}
                     -DMUTANT=${mutant} -DSCENES=${mutant_scenes} -DSCENES_ROOT=${CMAKE_CURRENT_SOURCE_DIR}/scenes
                     -DEVIDENCE_DIR=${CMAKE_BINARY_DIR}/test-out/mutants/${mutant}.${suffix}
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/mutant_is_killed.cmake)
    set_tests_properties(mutants.${mutant}.${suffix} PROPERTIES LABELS "mutants;${suffix}"
      SKIP_REGULAR_EXPRESSION "NotSupported" ENVIRONMENT "${backend_test_environment}")
  endforeach()
endforeach()
