# The scenes that get a generated deferred variant in this folder, and what
# every variant changes (README.md). suite/deferred_variants.cmake writes the
# variants at configure time and checks them; the test
# unit.scenes.deferred-variants-match-originals checks them again.

# Paths under suite/scenes. A pattern takes every scene of its folder, so an
# attenuation scene added later gets its variant too.
set(deferred_variant_originals
  "attenuation/*.json"
  "brdf/*.json"
  "cookies/*.json"
  "shadows/directional-bilinear.json"
  "shadows/spot-tent3x3.json"
  "shadows/point-bilinear.json"
  "shadows/spot-cookie-and-shadow.json"
  "shadowmask/strength-0-half-1.json")

# The variant's "pipeline" member, added after "camera". An original must not
# have one of its own.
set(deferred_variant_path "deferred")
set(deferred_variant_buffer "hdr32")

# The variant's description is this sentence (<BUFFER> and <ORIGINAL>, i.e.
# <group>/<name>, filled in), then the variant's note if it has one, then the
# original's description.
set(deferred_variant_intro "Deferred variant (light buffer <BUFFER>) of <ORIGINAL>: the same scene drawn through the G-buffer and one light volume per light, where the surface position comes from the stored window depth, not the rasteriser's interpolated position.")

# Notes, per variant name (<group>-<name>): what else that variant checks.
set(deferred_variant_note_brdf-metallic-1 "Here the light pass adds lights whose diffuse colour is 0: everything it adds is F0 times the lobe, read back from the G-buffer's material target.")
set(deferred_variant_note_brdf-translated-1e5 "Here V comes from the position the light pass reconstructs from depth, camera-relative, so it too must not see the 1e5 offset.")
set(deferred_variant_note_brdf-terms-srp "Here the G-buffer's base target carries ambient and lightmap times the BRDF's diffuse colour, and the material target metallic and smoothness for the light pass's lobes.")
set(deferred_variant_note_cookies-point-cube-seams-corner "Here the cube is sampled in the light pass at the position rebuilt from depth, through the point light's icosphere volume.")
set(deferred_variant_note_cookies-spot-cone-crosses-light-plane "Here the spot's cone volume bounds the light pass: pixels behind the light's plane are outside it and must stay unlit, as q.z <= 0 gives 0 forward.")
set(deferred_variant_note_shadows-directional-bilinear "Here the light pass samples the forward pass's shadow map at the position rebuilt from depth and the G-buffer's normal (the normal bias), so deferred must equal forward.")
set(deferred_variant_note_shadows-spot-tent3x3 "Here the spot's cone volume bounds the light pass, and its tent3x3 lookups happen at the rebuilt position.")
set(deferred_variant_note_shadows-point-bilinear "Here the cube map is sampled through the point light's icosphere volume at the rebuilt position, across the face seams.")
set(deferred_variant_note_shadows-spot-cookie-and-shadow "Here the light pass applies the cookie and the shadow of one light together.")
set(deferred_variant_note_shadowmask-strength-0-half-1 "Here the G-buffer's base target carries the lightmap (the demoted light) and its mask target the shadow mask, sampled where the fragment is, and the light pass applies each light's channel from it.")
