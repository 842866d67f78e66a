#include "backends/vulkan/vulkan_backend.h"

#include "backends/drawable_features.h"
#include "backends/vulkan/baked_textures.h"
#include "backends/vulkan/cluster_lists.h"
#include "backends/vulkan/cookie_textures.h"
#include "backends/vulkan/deferred_renderer.h"
#include "backends/vulkan/draw_timestamps.h"
#include "backends/vulkan/forward_pipeline.h"
#include "backends/vulkan/frame_resources.h"
#include "backends/vulkan/light_texture_set.h"
#include "backends/vulkan/pipeline_cache_file.h"
#include "backends/vulkan/readback.h"
#include "backends/vulkan/scene_geometry.h"
#include "backends/vulkan/scene_pass.h"
#include "backends/vulkan/shadow_maps.h"
#include "backends/vulkan/vulkan_device.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>

namespace backends::vulkan {
namespace {

constexpr std::uint64_t kNoTimeout = UINT64_MAX;

class VulkanBackend final : public Backend {
 public:
  explicit VulkanBackend(const BackendOptions& options)
      : options_(options),
        instance_(options.validation, options.driver),
        device_(instance_, options.device),
        cache_(device_),
        pipelines_(device_, cache_),
        mapDefaults_(device_, pipelines_.mapsSetLayout()),
        lightTextures_(device_.device, pipelines_.lightTextureSetLayout()),
        cookies_(device_, lightTextures_.set()),
        shadows_(device_, cache_, lightTextures_.set(), options.variant.mutant),
        clusters_(device_, pipelines_.clusterListsSetLayout()) {
    pool_ = vk::raii::CommandPool(device_.device,
                                  vk::CommandPoolCreateInfo{.flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                            .queueFamilyIndex = device_.queueFamily});
    vk::raii::CommandBuffers buffers(device_.device, vk::CommandBufferAllocateInfo{
                                                         .commandPool = *pool_,
                                                         .level = vk::CommandBufferLevel::ePrimary,
                                                         .commandBufferCount = 1});
    commands_ = std::move(buffers.front());
    fence_ = vk::raii::Fence(device_.device, vk::FenceCreateInfo{});
    if (canTimeDraws(device_)) timestamps_.emplace(device_);
    checkValidation("creating the device");
  }

  DeviceInfo device() const override { return device_.info; }

  void preparePipeline(const lighting::Frame& frame) override {
    requireDrawableFeatures(frame);
    if (isDeferred(frame)) {
      deferred().preparePipelines(frame);
      checkValidation("creating the deferred pipelines");
      return;
    }
    pipelines_.pipeline(shaders::constantValues(frame.features, options_.variant));
    checkValidation("creating the forward pipeline");
  }

  void prepareTextures(const lighting::Frame& frame) override {
    requireDrawableFeatures(frame);
    // The maps are uploaded once per prepared scene and bake; a CPU mutant
    // that swaps the bake hands over a new one.
    if (!maps_ || !maps_->isFor(*frame.prepared)) {
      maps_.reset();
      maps_.emplace(device_, mapDefaults_, pipelines_.mapsSetLayout(), frame.prepared);
      checkValidation("uploading the baked maps of " + frame.scene().sourcePath);
    }
    cookies_.update(frame);  // uploads a new scene's cookies; this frame's block and slots
    checkValidation("writing the cookies of " + frame.scene().sourcePath);
    shadows_.update(frame);  // this frame's shadow maps, blocks and slots (SPEC 3.9)
    checkValidation("preparing the shadow maps of " + frame.scene().sourcePath);
  }

  void draw(const lighting::Frame& frame) override {
    requireDrawableFeatures(frame);
    lastDrawMilliseconds_.reset();
    const lighting::ImageSize size = frame.scene().image;
    const vk::Extent2D extent{std::uint32_t(size.width), std::uint32_t(size.height)};
    if (!target_ || target_->color.extent != extent) {
      target_.reset();
      target_.emplace(device_, extent);
    }
    if (!geometry_ || geometry_->prepared != frame.prepared) {
      geometry_.reset();
      geometry_.emplace(device_, frame.prepared, packGeometry(*frame.prepared));
    }
    prepareTextures(frame);
    const std::string when = "drawing frame " + std::to_string(frame.index) + " of " + frame.scene().sourcePath;
    if (isDeferred(frame)) {
      drawDeferred(frame, when);
      return;
    }
    const std::size_t objectCount = frame.scene().objects.size();
    if (!uniforms_ || uniforms_->scene().objectCapacity() < objectCount) {
      uniforms_.reset();
      uniforms_.emplace(device_, pipelines_.setLayout(), objectCount);
    }
    uniforms_->scene().write(frame);
    clusters_.write(frame);

    const vk::raii::Pipeline& pipeline = pipelines_.pipeline(shaders::constantValues(frame.features, options_.variant));
    submit(
        [&](const vk::raii::CommandBuffer& cb) {
          if (timestamps_) timestamps_->recordBegin(cb);
          shadows_.record(cb, *geometry_);  // SPEC 3.9: the maps before the lighting that reads them
          if (timestamps_) timestamps_->recordShadowPassesEnd(cb);
          recordForwardPass(cb, pipeline);
          if (timestamps_) timestamps_->recordEnd(cb);
        },
        when);
    finishDraw(when);
  }

  std::optional<double> lastDrawDeviceMilliseconds() const override { return lastDrawMilliseconds_; }
  std::optional<double> lastShadowPassDeviceMilliseconds() const override { return lastShadowMilliseconds_; }

  imaging::Image readback() override {
    if (!drawn_) throw DriverError("readback() before any draw()");
    submit([&](const vk::raii::CommandBuffer& cb) { recordReadback(cb, *target_); }, "reading the image back");
    drawn_ = false;  // the colour target has left the attachment layout
    return stagingToImage(*target_);
  }

  std::vector<imaging::Image> readShadowMaps() override {
    if (!shadows_.any()) return {};
    submit([&](const vk::raii::CommandBuffer& cb) { shadows_.recordReadback(cb); }, "reading the shadow maps back");
    return shadows_.readbackImages();
  }

 private:
  static bool isDeferred(const lighting::Frame& frame) {
    return frame.scene().pipeline.path == lighting::RenderPath::Deferred;
  }

  // Made on the first deferred frame: forward-only runs never build it.
  DeferredRenderer& deferred() {
    if (!deferred_)
      deferred_.emplace(device_, cache_, pipelines_.mapsSetLayout(), pipelines_.lightTextureSetLayout(),
                        options_.variant);
    return *deferred_;
  }

  // SPEC 3.7: G-buffer, light and composite passes in one command buffer,
  // timed as a whole, into the same colour target as the forward pass.
  void drawDeferred(const lighting::Frame& frame, const std::string& when) {
    DeferredRenderer& renderer = deferred();
    renderer.prepareFrame(frame);
    checkValidation("preparing the deferred passes of " + frame.scene().sourcePath);
    submit(
        [&](const vk::raii::CommandBuffer& cb) {
          if (timestamps_) timestamps_->recordBegin(cb);
          shadows_.record(cb, *geometry_);  // the light pass samples the forward pass's maps
          if (timestamps_) timestamps_->recordShadowPassesEnd(cb);
          renderer.record(cb, *geometry_, *maps_, lightTextures_.set(), *target_);
          if (timestamps_) timestamps_->recordEnd(cb);
        },
        when);
    finishDraw(when);
  }

  // After a draw's submission: its device time, and the target is ready to read back.
  void finishDraw(const std::string& when) {
    lastShadowMilliseconds_.reset();
    if (timestamps_) {
      const double milliseconds = timestamps_->milliseconds();
      const double shadowMilliseconds = timestamps_->shadowPassMilliseconds();
      checkValidation(when + " (reading its timestamps)");
      lastDrawMilliseconds_ = milliseconds;
      if (shadows_.any()) lastShadowMilliseconds_ = shadowMilliseconds;
    }
    drawn_ = true;
  }

  void recordForwardPass(const vk::raii::CommandBuffer& cb, const vk::raii::Pipeline& pipeline) const {
    const std::array<vk::ImageMemoryBarrier2, 2> toAttachment{discardToColorAttachment(target_->color),
                                                              discardToDepthAttachment(target_->depth)};
    recordBarriers(cb, toAttachment);
    cb.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), kLightTextureSetIndex,
                          {lightTextures_.set()}, {});
    // The clustered mode's lists are the frame's, not an object's: bound once
    // per pass, where set 0 is bound again for every object's dynamic offset.
    cb.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *pipelines_.layout(), kClusterListsSetIndex,
                          {clusters_.set()}, {});
    // Background: value 0 (SPEC 6), alpha 1 (SPEC 8).
    const std::array<vk::RenderingAttachmentInfo, 1> color{clearedColor(target_->color, lighting::kBackgroundClear)};
    recordSceneObjectsPass(cb, *geometry_,
                           {.colors = color,
                            .depth = clearedDepth(target_->depth, vk::AttachmentStoreOp::eDontCare),
                            .extent = target_->color.extent,
                            .pipeline = *pipeline,
                            .layout = *pipelines_.layout(),
                            .bindUniforms =
                                [&](const vk::raii::CommandBuffer& commands, std::size_t object) {
                                  commands.bindDescriptorSets(vk::PipelineBindPoint::eGraphics,
                                                              *pipelines_.layout(), kSceneSetIndex,
                                                              {*uniforms_->descriptorSet()},
                                                              {uniforms_->scene().objectOffset(object)});
                                },
                            .maps = &*maps_});
  }

  // Records with `record`, submits, waits, and turns any validation message
  // into a DriverError.
  void submit(const std::function<void(const vk::raii::CommandBuffer&)>& record, const std::string& when) {
    commands_.reset();
    commands_.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
    record(commands_);
    commands_.end();
    const vk::CommandBuffer cb = *commands_;
    device_.device.resetFences({*fence_});
    device_.queue.submit(vk::SubmitInfo{.commandBufferCount = 1, .pCommandBuffers = &cb}, *fence_);
    if (device_.device.waitForFences({*fence_}, VK_TRUE, kNoTimeout) != vk::Result::eSuccess)
      throw DriverError("waiting for the Vulkan queue failed while " + when);
    checkValidation(when);
  }

  void checkValidation(const std::string& when) {
    if (ValidationLog* log = instance_.validationLog()) log->throwIfAny(when);
  }

  BackendOptions options_;
  VulkanInstance instance_;
  VulkanDevice device_;
  PipelineCacheFile cache_;
  ForwardPipelines pipelines_;
  BakedMapDefaults mapDefaults_;
  LightTextureSet lightTextures_;  // set 3: the cookies' and the shadow maps' bindings
  CookieTextures cookies_;
  ShadowMaps shadows_;
  ClusterLists clusters_;  // set 2 of the forward pass: the clustered mode's lists
  vk::raii::CommandPool pool_{nullptr};
  vk::raii::CommandBuffer commands_{nullptr};
  vk::raii::Fence fence_{nullptr};
  std::optional<RenderTarget> target_;
  std::optional<SceneGeometry> geometry_;
  std::optional<SceneBakedTextures> maps_;
  std::optional<ForwardUniforms> uniforms_;
  std::optional<DeferredRenderer> deferred_;
  std::optional<DrawTimestamps> timestamps_;  // empty when the queue writes no timestamps
  std::optional<double> lastDrawMilliseconds_;
  std::optional<double> lastShadowMilliseconds_;  // the shadow passes' share of it
  bool drawn_ = false;
};

// Vulkan-Hpp reports failures as vk::SystemError; the commands map
// DriverError to exit 4 with the message.
template <class F>
auto translatingVulkanErrors(F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const vk::SystemError& e) {
    throw DriverError(std::string("Vulkan: ") + e.what());
  }
}

}  // namespace

BackendEntry vulkanBackendEntry() {
  BackendEntry entry;
  entry.name = "vulkan";
  entry.listDevices = [](const BackendOptions& options) {
    return translatingVulkanErrors([&] {
      VulkanInstance instance(options.validation, options.driver);
      const std::string driverOption = options.driver.empty() ? "" : "--driver " + options.driver + " ";
      std::vector<DeviceInfo> devices;
      for (const vk::raii::PhysicalDevice& d : instance.physicalDevices()) {
        devices.push_back(describeDevice(d));
        devices.back().selectedBy = driverOption + "--device " + std::to_string(devices.size() - 1);
      }
      return devices;
    });
  };
  entry.create = [](const BackendOptions& options) -> std::unique_ptr<Backend> {
    return translatingVulkanErrors([&] { return std::make_unique<VulkanBackend>(options); });
  };
  return entry;
}

}  // namespace backends::vulkan
