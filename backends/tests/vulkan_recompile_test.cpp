// Drawing a frame again compiles nothing on lavapipe. Mesa 22.3's lavapipe
// folds the values of up to four uniforms that steer a loop or a branch into
// the shader and compiles it again with LLVM whenever their buffer is bound
// anew, without keeping the variants: once per frame for a frame's blocks,
// once per draw for an object's (docs/vendors.md, "lavapipe recompiles").
// The shaders read every such uniform at an offset the compiler cannot know
// (OPAQUE_READ, shaders/light_data.glsl); this test holds them to it.
//
// It counts LLVM modules: every compile of a shader variant, and every other
// function llvmpipe generates, begins with LLVMModuleCreateWithNameInContext.
// This executable exports its own definition of that function (ENABLE_EXPORTS),
// which the driver's calls bind to before libLLVM's, and forwards to it.
#include "backends/backend.h"
#include "baking/bake.h"
#include "lighting/frame.h"
#include "scene_input/scene_loader.h"

#include <gtest/gtest.h>

#include <dlfcn.h>
#include <link.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace {
std::atomic<long> modulesCreated{0};
}

namespace {

using CreateModule = void* (*)(const char*, void*);

// libLLVM's own definition. The driver loaded libLLVM privately (the Vulkan
// loader opens drivers RTLD_LOCAL), so RTLD_NEXT does not see it: find the
// loaded library whose name says LLVM and ask it.
CreateModule llvmsOwnCreateModule() {
  CreateModule found = nullptr;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* out) {
        if (!info->dlpi_name || !std::strstr(info->dlpi_name, "libLLVM")) return 0;
        void* library = dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD);
        if (!library) return 0;
        *static_cast<CreateModule*>(out) =
            reinterpret_cast<CreateModule>(dlsym(library, "LLVMModuleCreateWithNameInContext"));
        dlclose(library);  // still loaded: the driver holds it
        return *static_cast<CreateModule*>(out) ? 1 : 0;
      },
      &found);
  if (!found) {
    std::fprintf(stderr, "vulkan_recompile_tests: LLVMModuleCreateWithNameInContext called, but no libLLVM is loaded\n");
    std::abort();
  }
  return found;
}

}  // namespace

extern "C" void* LLVMModuleCreateWithNameInContext(const char* name, void* context) {
  static const CreateModule llvm = llvmsOwnCreateModule();
  ++modulesCreated;
  return llvm(name, context);
}

namespace {

// A backend on lavapipe, or null with the reason to skip: only a driver that
// compiles with LLVM creates the modules counted here, so on any other a
// count of zero would be a pass that checked nothing.
std::unique_ptr<backends::Backend> lavapipeOrNull(bool specialised, std::string& whyNot) {
  backends::BackendOptions options;
  options.validation = true;
  options.variant.specialised = specialised;
  try {
    auto backend = backends::findBuiltBackendEntry("vulkan")->create(options);
    if (backend->device().name.find("llvmpipe") != std::string::npos) return backend;
    whyNot = backend->device().name + " is not lavapipe";
  } catch (const backends::NotSupportedError& e) {
    whyNot = std::string("no Vulkan device: ") + e.what();
  }
  return nullptr;
}

// One scene per way a uniform steers the shaders: the frame's light counts,
// an object's list (per draw), the legacy vertex loop, the cookie and shadow
// slots, the shadow mask, the lightmap, the BRDF's material, the deferred
// light pass (a block per light).
const char* const kScenes[] = {
    "limits/popping-64.json",
    "per-object/eleven-lights.json",
    "legacy/four-pixel-four-vertex.json",
    "legacy/cookie-vertex-light.json",
    "cookies/alpha-channel.json",
    "shadows/directional-bilinear.json",
    "shadowmask/four-overlapping-mixed.json",
    "baked/shadows-box-on-plane.json",
    "brdf/metallic-1.json",
    "deferred/attenuation-point-5mm-above-floor.json",
};

// Draws every scene twice on `backend` and expects no module in the second draw.
void expectRedrawsCompileNothing(backends::Backend& backend) {
  for (const char* scene : kScenes) {
    const auto prepared =
        baking::prepareBakedScene(scene_input::loadSceneFile((std::filesystem::path(LIGHTCTS_SCENES_DIR) / scene).string()));
    const lighting::Frame frame = lighting::prepareFrame(prepared, 0);
    backend.draw(frame);  // the first draw compiles what the frame needs
    const long before = modulesCreated.load();
    backend.draw(frame);
    EXPECT_EQ(modulesCreated.load() - before, 0) << scene << ": the second draw of the same frame compiled LLVM modules";
  }
}

TEST(VulkanRecompiles, TheCounterSeesTheDriversCompiles) {
  std::string whyNot;
  auto backend = lavapipeOrNull(true, whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  const long before = modulesCreated.load();
  const auto prepared = baking::prepareBakedScene(
      scene_input::loadSceneFile((std::filesystem::path(LIGHTCTS_SCENES_DIR) / kScenes[0]).string()));
  backend->draw(lighting::prepareFrame(prepared, 0));
  EXPECT_GT(modulesCreated.load() - before, 0) << "a first draw compiled nothing: the counter is not bound";
}

TEST(VulkanRecompiles, RedrawingAFrameCompilesNothing) {
  std::string whyNot;
  auto backend = lavapipeOrNull(true, whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  expectRedrawsCompileNothing(*backend);
}

TEST(VulkanRecompiles, RedrawingAFrameWithTheFullShaderCompilesNothing) {
  std::string whyNot;
  auto backend = lavapipeOrNull(false, whyNot);
  if (!backend) GTEST_SKIP() << whyNot;
  expectRedrawsCompileNothing(*backend);
}

}  // namespace
