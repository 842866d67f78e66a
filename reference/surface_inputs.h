// How far the position and normal a fragment stage gets may be from the
// exact ones, from the operations that make them, each bounded by the
// precision table (reference/float_bound.h): forward.vert's model
// transform (the uploaded float matrix times the uploaded float vertex) and
// normalize of the rotated normal, the rasteriser's perspective-correct blend
// of the three vertices (Vulkan gives the formula, "Basic Polygon
// Rasterization", and no precision for it: lightcts takes each of its
// operations at the table's allowance), and forward.frag's normalize. The
// light terms (reference/light_terms.h) take these as their inputs' errors.
#pragma once

#include "lighting/transform.h"

#include <glm/mat4x4.hpp>

#include <array>

namespace reference {

using lighting::Vec3;

// A vertex as the mesh holds it: what is uploaded, as float, to the vertex stage.
struct MeshVertex {
  Vec3 local{0.0};
  Vec3 localNormal{0.0, 1.0, 0.0};
};

// Per component, bounds on |float32 - exact| of the camera-relative position
// and of the unit normal.
struct SurfaceErrors {
  double position = 0;
  double normal = 0;
};

// At a point of a triangle with (3D) barycentrics `b` of its vertices, drawn
// with `transform`, a camera at `camera` and `viewProjection` (camera-relative
// world to clip, lighting::CameraView::cameraRelativeViewProjection).
// `nearestW`: the clip w of the near plane (the near distance; 1 for an
// orthographic view), where the clipper puts the vertices that replace one
// behind it.
SurfaceErrors fragmentInputErrors(const lighting::ObjectTransform& transform, const Vec3& camera,
                                  const glm::dmat4& viewProjection, double nearestW,
                                  const std::array<MeshVertex, 3>& vertices, const std::array<double, 3>& b);

// At a vertex (SPEC 4's vertex lights): the vertex stage's alone.
SurfaceErrors vertexInputErrors(const lighting::ObjectTransform& transform, const Vec3& camera, const MeshVertex& vertex);

// Where no mesh is at hand: a vertex whose camera-relative coordinates are
// at most `magnitude` (a model transform of identity rotation and scale whose
// translation and local position share it), blended with equal weights by an
// orthographic view.
SurfaceErrors inputErrorsOfMagnitude(double magnitude);

}  // namespace reference
