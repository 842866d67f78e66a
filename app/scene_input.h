// Loading the scene and frame a command works on. Bad input becomes an
// InputError whose message is printed as is, and exit status 2.
#pragma once

#include "app/commands.h"
#include "lighting/frame.h"

#include <functional>
#include <memory>
#include <stdexcept>

namespace app {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SceneInput {
  std::shared_ptr<const lighting::PreparedScene> prepared;
  lighting::Frame frame;
};

// Throws InputError for an unreadable or invalid scene, or a frame out of range.
// `bake`: commands that render bake the scene's lightmaps here (or read them
// from the bake cache); `lightcts lights` only selects and needs no maps.
SceneInput loadSceneInput(const SceneArguments& args, bool bake = true);

// Runs a command body, turning InputError and SceneLoadError into exit 2 and
// anything unexpected into exit 4, each with one line on `err`.
int guardCommand(std::ostream& err, const std::function<int()>& body);

// Creates the output folder (and parents); throws InputError when it cannot.
void makeOutputDirectory(const std::string& dir);

}  // namespace app
