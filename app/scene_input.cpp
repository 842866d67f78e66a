#include "app/scene_input.h"
#include "imaging/image_codec_loader.h"

#include "app/exit_status.h"
#include "backends/backend.h"
#include "baking/bake.h"
#include "imaging/image_files.h"
#include "scene_input/scene_loader.h"

#include <filesystem>
#include <functional>
#include <iostream>
#include <ostream>

namespace app {

SceneInput loadSceneInput(const SceneArguments& args, bool bake) {
  SceneInput input;
  lighting::Scene scene = scene_input::loadSceneFile(args.scenePath);
  // What an import ignored (SPEC 2.1) is said once, on stderr: stdout may
  // be a command's JSON.
  for (const std::string& warning : scene.warnings) std::cerr << "lightcts: warning: " << warning << "\n";
  const int count = scene.frames.count;
  if (args.frame < 0 || args.frame >= count)
    throw InputError(args.scenePath + ": --frame " + std::to_string(args.frame) + " is out of range: the scene has " +
                     std::to_string(count) + " frame(s), 0.." + std::to_string(count - 1));
  // Scenes with lightmaps are baked here (or read from the bake cache), so
  // every command renders them with their maps (SPEC 3.6).
  input.prepared = bake ? baking::prepareBakedScene(std::move(scene)) : lighting::prepareScene(std::move(scene));
  input.frame = lighting::prepareFrame(input.prepared, args.frame);
  return input;
}

int guardCommand(std::ostream& err, const std::function<int()>& body) {
  try {
    return body();
  } catch (const scene_input::SceneLoadError& e) {
    err << "lightcts: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const InputError& e) {
    err << "lightcts: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const imaging::ImageModuleError& e) {
    err << "lightcts: " << e.what() << "\n";
    return kExitInternalError;
  } catch (const imaging::ImageFileError& e) {
    err << "lightcts: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const backends::NotSupportedError& e) {
    err << "lightcts: not supported here (NotSupported): " << e.what() << "\n";
    return kExitNotSupported;
  } catch (const backends::DriverError& e) {
    err << "lightcts: driver error: " << e.what() << "\n";
    return kExitInternalError;
  } catch (const std::exception& e) {
    err << "lightcts: internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
}

void makeOutputDirectory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError("cannot create output folder " + dir + (ec ? ": " + ec.message() : ": not a folder"));
}

}  // namespace app
