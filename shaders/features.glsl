// Specialization constants: the features a frame uses (lighting::ShaderFeatures).
// A backend turns off what a scene does not use, so a point-light-only scene
// runs the short shader; every default is "on", which is the full shader.
// The constant ids are shared with shaders/shader_constants.h.
#ifndef LIGHTCTS_FEATURES_GLSL
#define LIGHTCTS_FEATURES_GLSL

layout(constant_id = 0) const bool DIRECTIONAL_LIGHTS = true;
layout(constant_id = 1) const bool POINT_LIGHTS = true;
layout(constant_id = 2) const bool SPOT_LIGHTS = true;
// Per-object lists (srp with lights_per_object, and always in legacy).
layout(constant_id = 3) const bool PER_OBJECT_LISTS = true;
// The legacy profile: list positions 0-3 per pixel, 4-7 per vertex (SPEC 4),
// and directional lights packed among the others.
layout(constant_id = 4) const bool VERTEX_LIGHTS = true;
layout(constant_id = 5) const bool SHADOW_MASK = true;
layout(constant_id = 6) const bool AMBIENT = true;
// Test only: a deliberately wrong variant of the model (mutants.glsl). 0, the
// model itself, is the only value a shipped pipeline uses.
layout(constant_id = 7) const int MUTANT = 0;
// Baked light: the object's lightmap is sampled and added (SPEC 3.6).
layout(constant_id = 8) const bool LIGHTMAP = true;
// Deferred path (SPEC 3.7): the light buffer is ldr8, so the light pass
// writes exp2(-c) and the composite decodes -log2(max(x, 1/255)). The full
// shader (every constant on) asks DeferredFrameBlock.bufferFormat (deferred_data.glsl).
layout(constant_id = 9) const bool LDR8_BUFFER = true;
// The srp BRDF (SPEC 3.8): some material has it, so diffuse and F0 come from
// metallic and the specular lobe is evaluated; off, every material is Lambert.
layout(constant_id = 10) const bool SPECULAR_BRDF = true;
// Light cookies (SPEC 3.10): some kept light has one, so lights carry a
// cookie slot and the cookie textures are sampled (cookies.glsl).
layout(constant_id = 11) const bool COOKIES = true;
// Real-time shadow maps (SPEC 3.9): some kept light has one, so lights carry
// a shadow slot and the depth textures are looked up (shadows.glsl).
layout(constant_id = 12) const bool SHADOW_MAPS = true;
// Forward+ (a benchmark mode, never the model's): the fragment
// loops over its cluster's lights (clusters.glsl) instead of every kept one.
// The full shader asks FrameBlock.lightCounts.w.
layout(constant_id = 13) const bool CLUSTERED_LIGHTS = true;
// A driver probe, on in every shipped pipeline: the uniforms that steer loops
// and branches are read at an offset the compiler cannot know (light_data.glsl,
// opaque()); off, at their constant offsets (render_bench --uniform_reads=constant).
layout(constant_id = 14) const bool OPAQUE_UNIFORM_READS = true;
// The cookie and shadow-map slots in use, each kind's first N (the CPU fills
// them in order): the others are not looked up. The full shader has them all.
layout(constant_id = 15) const int COOKIE_TEXTURES = 4;
layout(constant_id = 16) const int COOKIE_CUBES = 2;
layout(constant_id = 17) const int SHADOW_MAP_TEXTURES = 4;
layout(constant_id = 18) const int SHADOW_MAP_CUBES = 2;
// Some 2D shadow-map slot filters tent3x3 (four bilinear compares): without
// it the tent's code is left out, which llvmpipe and lavapipe would otherwise
// run beside the single compare of every slot (they run both sides of a branch).
layout(constant_id = 19) const bool SHADOW_TENT = true;
// A deferred light pass draws one light: its pipeline looks up that light's
// cookie slot and shadow slot alone (-2: the light has none), whatever other
// slots the frame fills. -1, the default: every slot in use (the forward
// pass, the full shader).
layout(constant_id = 20) const int LIGHT_COOKIE_SLOT = -1;
layout(constant_id = 21) const int LIGHT_SHADOW_SLOT = -1;

#endif
