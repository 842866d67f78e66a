#include "backends/gl/cluster_lists.h"

#include "backends/backend.h"
#include "backends/gl/program_builder.h"
#include "lighting/gpu_packing.h"
#include "lighting/light_clusters.h"

#include <cstdint>
#include <string>
#include <vector>

namespace backends::gl {

void bindClusterListsInterface(const GlFunctions& gl, GLuint program) {
  bindSamplers(gl, program, shaders::binding::kClusterLists);
}

ClusterLists::ClusterLists(const GlFunctions& gl)
    : gl_(gl), buffer_(makeBuffer(gl)), texture_(makeTexture(gl)) {
  gl_.glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels_);
  // The texture views the buffer once; glBufferData may reallocate the
  // store, and the texture follows it. A name from glGenBuffers is a buffer
  // only once bound: glTexBuffer refuses it before (GL_INVALID_OPERATION).
  const std::uint32_t zero = 0;
  gl_.glBindBuffer(GL_TEXTURE_BUFFER, buffer_.get());
  gl_.glBufferData(GL_TEXTURE_BUFFER, sizeof(zero), &zero, GL_STREAM_DRAW);
  gl_.glBindBuffer(GL_TEXTURE_BUFFER, 0);
  gl_.glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
  gl_.glTexBuffer(GL_TEXTURE_BUFFER, GL_R32UI, buffer_.get());
  gl_.glBindTexture(GL_TEXTURE_BUFFER, 0);
  gl_.check("creating the cluster lists' texture buffer");
}

void ClusterLists::update(const lighting::Frame& frame) {
  const std::vector<std::uint32_t> texels = lighting::packFrameClusterTexels(frame);
  if (texels.size() > std::size_t(maxTexels_))
    throw NotSupportedError("the clustered mode's lists are " + std::to_string(texels.size()) +
                            " texels; this driver's texture buffers hold " + std::to_string(maxTexels_) +
                            " (choose larger tiles or fewer slices)");
  gl_.glBindBuffer(GL_TEXTURE_BUFFER, buffer_.get());
  gl_.glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(texels.size() * sizeof(std::uint32_t)), texels.data(),
                   GL_STREAM_DRAW);
  gl_.glBindBuffer(GL_TEXTURE_BUFFER, 0);
  gl_.glActiveTexture(GL_TEXTURE0 + shaders::binding::kClusterLists.glUnit());
  gl_.glBindTexture(GL_TEXTURE_BUFFER, texture_.get());
  gl_.glActiveTexture(GL_TEXTURE0);
  gl_.check("uploading the cluster lists");
}

}  // namespace backends::gl
