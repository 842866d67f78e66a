// The light pass's raster and blend state (SPEC 3.7, docs/model.md "Deferred
// path"), written out here by hand from the volume rule: back faces behind or
// on the surface (cull FRONT, GREATER_OR_EQUAL), no depth writes, depth clamp;
// the full-screen triangle with no culling and ALWAYS; the mutant's front
// faces with LESS_OR_EQUAL on icospheres only; hdr sums from 0, ldr8
// multiplies from 1.
#include "lighting/deferred_lights.h"
#include "lighting/raster_state.h"

#include <gtest/gtest.h>

namespace lighting {
namespace {

TEST(RasterState, OpaqueSurfacesAreSpec1) {
  EXPECT_EQ(kOpaqueSurfaceState.cull, CullMode::Back);
  EXPECT_EQ(kOpaqueSurfaceState.depthTest, DepthCompare::Less);
  EXPECT_TRUE(kOpaqueSurfaceState.depthWrite);
  EXPECT_FALSE(kOpaqueSurfaceState.depthClamp);
}

TEST(RasterState, ModelVolumesDrawBackFacesBehindTheSurface) {
  const RasterState behind{CullMode::Front, DepthCompare::GreaterOrEqual, false, true};
  EXPECT_EQ(lightVolumeRasterState(LightVolumeShape::Icosphere, VolumeRule::Model), behind);
  EXPECT_EQ(lightVolumeRasterState(LightVolumeShape::Pyramid, VolumeRule::Model), behind);
  const RasterState fullScreen{CullMode::None, DepthCompare::Always, false, false};
  EXPECT_EQ(lightVolumeRasterState(LightVolumeShape::FullScreen, VolumeRule::Model), fullScreen);
}

TEST(RasterState, OutsideOnlyMutantChangesIcospheresOnly) {
  const RasterState inFront{CullMode::Back, DepthCompare::LessOrEqual, false, true};
  EXPECT_EQ(lightVolumeRasterState(LightVolumeShape::Icosphere, VolumeRule::OutsideOnlyMutant), inFront);
  EXPECT_EQ(lightVolumeRasterState(LightVolumeShape::Pyramid, VolumeRule::OutsideOnlyMutant),
            lightVolumeRasterState(LightVolumeShape::Pyramid, VolumeRule::Model));
  EXPECT_EQ(lightVolumeRasterState(LightVolumeShape::FullScreen, VolumeRule::OutsideOnlyMutant),
            lightVolumeRasterState(LightVolumeShape::FullScreen, VolumeRule::Model));
}

TEST(RasterState, NoVolumeWritesDepth) {
  for (LightVolumeShape shape : {LightVolumeShape::FullScreen, LightVolumeShape::Icosphere, LightVolumeShape::Pyramid})
    for (VolumeRule rule : {VolumeRule::Model, VolumeRule::OutsideOnlyMutant})
      EXPECT_FALSE(lightVolumeRasterState(shape, rule).depthWrite);
}

TEST(LightBufferState, ClearIsTheBlendsIdentity) {
  for (DeferredBuffer hdr : {DeferredBuffer::Hdr32, DeferredBuffer::Hdr16}) {
    EXPECT_EQ(lightBufferState(hdr).blend, LightBlend::Add);
    EXPECT_EQ(lightBufferState(hdr).clearValue, 0.0f);
  }
  EXPECT_EQ(lightBufferState(DeferredBuffer::Ldr8).blend, LightBlend::Multiply);
  EXPECT_EQ(lightBufferState(DeferredBuffer::Ldr8).clearValue, 1.0f);
}

}  // namespace
}  // namespace lighting
