// The deferred path's light buffers (SPEC 3.7) in the reference: what the
// model's value is (ldr8 saturates the light sum at log2(255)) and how far a
// correct implementation may land from it because of the buffer's format
// and the position it reconstructs from depth. docs/tolerances.md "Deferred
// buffers" derives every bound; the constants are in tolerance_model.h.
#pragma once

#include "lighting/camera_view.h"
#include "lighting/scene.h"

namespace reference {

// The light sum the decode returns for a true per-channel sum S >= 0 of the
// lights' A * term: S for hdr, min(S, log2(255)) for ldr8.
double decodedLightSum(lighting::DeferredBuffer buffer, double lightSum);

// hdr16: the half roundings of `contributing` additive blends (lights whose
// A * term is > 0 in this channel) of a sum that ends at S:
// (k + 1) 2^-11 S + 2 k kHalfFlushFloor.
double hdr16BlendBound(double lightSum, int contributing);

// ldr8: the largest |decoded - min(S, log2 255)| a correct implementation can
// show: the stored value is a grid point n/255 within dx of exp2(-S), with
// dx = (2k - 1) kUnormRoundingError + the float arithmetic (the light sum's
// own bound `sumBound`, exp2 and the blend products), plus the decode's log2.
double ldr8DecodeBound(double lightSum, int contributing, double sumBound);

// How far the light pass's position, reconstructed from the stored window
// depth and the pixel's NDC through the float32 inverse view-projection, may
// be from a surface point the sub-pixel term admits (world units).
// `vertexSnap`: how far a vertex may snap (tolerance::vertexSnapPx); the
// G-buffer's depth comes from a snapped triangle, the light pass's ray from
// the pixel centre.
double reconstructionPositionError(const lighting::CameraView& view, const lighting::Vec3& p, double vertexSnap);

}  // namespace reference
