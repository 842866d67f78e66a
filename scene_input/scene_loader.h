// Loading and validating scene files (SPEC section 2). A scene that loads is
// complete and within range; anything else throws SceneLoadError, whose message
// names the file, the JSON path, the line and column where known, and what was
// expected. The command line turns it into exit status 2.
#pragma once

#include "lighting/scene.h"

#include <stdexcept>
#include <string>
#include <string_view>

namespace scene_input {

struct SceneError {
  std::string file;      // as given by the caller
  std::string jsonPath;  // RFC 6901 pointer, e.g. "/lights/3/range"; "" for the whole document
  int line = 0;          // 1-based; 0 when unknown
  int column = 0;        // 1-based; 0 when unknown
  std::string message;   // what was expected, and what was found

  // "FILE:LINE:COLUMN: /json/path: message" (line and column left out when unknown).
  std::string format() const;
};

class SceneLoadError : public std::runtime_error {
 public:
  explicit SceneLoadError(SceneError error);
  const SceneError& error() const { return error_; }

 private:
  SceneError error_;
};

// Reads and validates a scene file; throws SceneLoadError (also for a missing or
// unreadable file, with an empty JSON path).
lighting::Scene loadSceneFile(const std::string& path);

// Validates scene text; `sourceName` is used as the file name in messages.
lighting::Scene loadSceneText(std::string_view text, const std::string& sourceName);

}  // namespace scene_input
