// A value of a parsed JSON document with its RFC 6901 pointer, so that
// whatever is wrong with it can name where it is (SPEC 2). The one way this
// folder walks a document: the scene reader (scene_loader.cpp) and the glTF
// shape checks (gltf_json_checks.cpp) both move through theirs with it.
#pragma once

#include "scene_input/json_locations.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace scene_input {

template <typename Json>
struct JsonCursor {
  const Json& value;
  std::string pointer;  // "" for the document itself

  static JsonCursor root(const Json& document) { return {document, ""}; }

  // The pointer of the member `key`, whether or not it is there (an error
  // about a missing key names where it would be).
  std::string pointerTo(std::string_view key) const { return pointer + "/" + escapeJsonPointerToken(key); }

  // The member `key` of an object; nullopt when absent (or not an object).
  std::optional<JsonCursor> member(std::string_view key) const {
    if (!value.is_object()) return std::nullopt;
    const auto found = value.find(key);
    if (found == value.end()) return std::nullopt;
    return JsonCursor{*found, pointerTo(key)};
  }

  // Element `i` of an array, i < value.size().
  JsonCursor element(std::size_t i) const { return {value[i], pointer + "/" + std::to_string(i)}; }

  // A member met while iterating the object's items().
  JsonCursor item(std::string_view key, const Json& member) const { return {member, pointerTo(key)}; }
};

}  // namespace scene_input
