// Source positions for JSON values. nlohmann-json keeps none, so the scene
// loader (SPEC 2: errors name the line and column where they can) scans the
// text a second time on the error path to find where a value starts.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scene_input {

// 1-based line and column; the column counts characters (UTF-8 code points),
// not bytes, so it matches what an editor shows. A tab counts as one.
struct TextPosition {
  int line = 0;
  int column = 0;
};

// One value of a JSON document, in document order.
struct JsonValueSpan {
  std::string pointer;      // RFC 6901, "" for the root
  std::size_t keyOffset;    // byte offset of the member's key; npos for array elements and the root
  std::size_t valueOffset;  // byte offset where the value starts
  std::size_t valueLength;  // bytes of the value's text
};

// Every value of `text` with its pointer and offsets. The scan stops quietly at
// the first malformed spot (or beyond a nesting depth no scene needs), keeping
// what it found before it.
std::vector<JsonValueSpan> scanJsonValues(std::string_view text);

// The line and column of byte `offset` (clamped to the end of the text).
TextPosition textPositionAt(std::string_view text, std::size_t offset);

enum class JsonLocationTarget { Value, Key };

// Where the value at `pointer` starts, or with Target::Key where its key starts
// (for an unknown key; falls back to the value for array elements and the
// root). nullopt when the pointer names nothing in the text. If a key repeats,
// the last one counts, as it does in nlohmann-json.
std::optional<TextPosition> locateJsonPointer(std::string_view text, std::string_view pointer,
                                              JsonLocationTarget target = JsonLocationTarget::Value);

// "~" -> "~0" and "/" -> "~1" (RFC 6901 section 3), so a key can join a pointer.
std::string escapeJsonPointerToken(std::string_view token);

// The reverse: "~1" -> "/" and "~0" -> "~".
std::string unescapeJsonPointerToken(std::string_view token);

}  // namespace scene_input
