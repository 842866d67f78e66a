// SPEC 3.8, the custom pipeline's BRDF, in double precision: what a material
// turns into (diffuse colour, F0, roughness), the view vector, and the
// specular lobe. The reference calls these; the GPU copy is
// shaders/lighting.glsl (materialBrdf, viewDirection, specularStrength).
#pragma once

#include "lighting/camera_view.h"
#include "lighting/scene.h"

namespace lighting {

constexpr double kMinReflectivity = 0.04;      // SPEC 3.8: oneMinusReflectivity = 0.96 (1 - metallic)
constexpr double kLobeDenominatorOffset = 1.00001;  // SPEC 3.8: d2 = square(nh2 (r2 - 1) + 1.00001)
constexpr double kMinLh2 = 0.1;                // SPEC 3.8: max(0.1, lh2)
constexpr double kSafeNormalizeFloor = 1.17549435e-38;  // SPEC 3.8: SafeNormalize's max(dot(v, v), FLT_MIN)

// What a material contributes to SPEC 3's sum. Lambert: diffuse = A, no lobe
// (the sum of 3.1-3.2 as written). srp: 3.8's diffuse and F0.
struct MaterialBrdf {
  Vec3 diffuse{1.0};   // multiplies ambient, lightmap and every light's radiance
  Vec3 specular{0.0};  // F0: multiplies radiance * specularStrength
  double roughness = 0;
  bool lobe = false;   // srp: the specular lobe is evaluated
};
MaterialBrdf materialBrdf(const Object& object);

// SPEC 3.8: V = normalize(cameraPosition - p); orthographic: the unit vector
// opposite the view direction, whatever p is.
Vec3 viewDirection(const CameraView& view, const Vec3& p);

// SPEC 3.8: SafeNormalize(v) = v * inversesqrt(max(dot(v, v), FLT_MIN)), so
// the zero vector (L = -V) gives 0, never NaN.
Vec3 safeNormalize(const Vec3& v);

// SPEC 3.8's specularStrength for unit N, V, L and a roughness.
double specularStrength(const Vec3& N, const Vec3& V, const Vec3& L, double roughness);

}  // namespace lighting
