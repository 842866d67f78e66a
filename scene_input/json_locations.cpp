#include "scene_input/json_locations.h"

#include <string>

namespace scene_input {

namespace {

// Deeper than any scene; it keeps a hostile file from exhausting the stack.
constexpr int kMaxDepth = 256;

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

void appendUtf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// A recursive walk that records where each value starts. It only needs to be
// right for text that nlohmann-json accepted; on anything else it stops.
class JsonScanner {
 public:
  explicit JsonScanner(std::string_view text) : text_(text) {}

  std::vector<JsonValueSpan> scan() {
    if (text_.starts_with(kByteOrderMark)) pos_ = kByteOrderMark.size();
    skipWhitespace();
    scanValue("", std::string_view::npos, 0);
    return std::move(spans_);
  }

 private:
  bool scanValue(const std::string& pointer, std::size_t keyOffset, int depth) {
    if (pos_ >= text_.size() || depth > kMaxDepth) return false;
    const std::size_t index = spans_.size();
    spans_.push_back({pointer, keyOffset, pos_, 0});
    bool ok = false;
    switch (text_[pos_]) {
      case '{': ok = scanObject(pointer, depth); break;
      case '[': ok = scanArray(pointer, depth); break;
      case '"': ok = scanString(nullptr); break;
      default: ok = scanScalar(); break;
    }
    spans_[index].valueLength = pos_ - spans_[index].valueOffset;
    return ok;
  }

  bool scanObject(const std::string& pointer, int depth) {
    ++pos_;  // '{'
    skipWhitespace();
    if (consume('}')) return true;
    while (true) {
      skipWhitespace();
      const std::size_t keyOffset = pos_;
      std::string key;
      if (!scanString(&key)) return false;
      skipWhitespace();
      if (!consume(':')) return false;
      skipWhitespace();
      if (!scanValue(pointer + "/" + escapeJsonPointerToken(key), keyOffset, depth + 1)) return false;
      skipWhitespace();
      if (consume('}')) return true;
      if (!consume(',')) return false;
    }
  }

  bool scanArray(const std::string& pointer, int depth) {
    ++pos_;  // '['
    skipWhitespace();
    if (consume(']')) return true;
    for (std::size_t index = 0;; ++index) {
      skipWhitespace();
      if (!scanValue(pointer + "/" + std::to_string(index), std::string_view::npos, depth + 1)) {
        return false;
      }
      skipWhitespace();
      if (consume(']')) return true;
      if (!consume(',')) return false;
    }
  }

  // Reads a string starting at its opening quote; decodes it into `out` when
  // given, since a key must match the unescaped name nlohmann-json stores.
  bool scanString(std::string* out) {
    if (!consume('"')) return false;
    while (pos_ < text_.size()) {
      const char c = text_[pos_++];
      if (c == '"') return true;
      if (c != '\\') {
        if (out) *out += c;
        continue;
      }
      if (pos_ >= text_.size()) return false;
      const char escape = text_[pos_++];
      if (escape == 'u') {
        char32_t codePoint = 0;
        if (!readUtf16Escape(codePoint)) return false;
        if (out) appendUtf8(*out, codePoint);
      } else if (out) {
        *out += decodeSimpleEscape(escape);
      }
    }
    return false;
  }

  // After "\u": four hex digits, and a second "\uXXXX" for a surrogate pair.
  bool readUtf16Escape(char32_t& codePoint) {
    char32_t unit = 0;
    if (!readHex4(unit)) return false;
    codePoint = unit;
    const bool highSurrogate = unit >= 0xD800 && unit <= 0xDBFF;
    if (highSurrogate && text_.substr(pos_).starts_with("\\u")) {
      pos_ += 2;
      char32_t low = 0;
      if (!readHex4(low)) return false;
      codePoint = 0x10000 + ((unit - 0xD800) << 10) + (low - 0xDC00);
    }
    return true;
  }

  bool readHex4(char32_t& value) {
    if (pos_ + 4 > text_.size()) return false;
    value = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = text_[pos_++];
      int digit = 0;
      if (c >= '0' && c <= '9') {
        digit = c - '0';
      } else if (c >= 'a' && c <= 'f') {
        digit = c - 'a' + 10;
      } else if (c >= 'A' && c <= 'F') {
        digit = c - 'A' + 10;
      } else {
        return false;
      }
      value = value * 16 + static_cast<char32_t>(digit);
    }
    return true;
  }

  static char decodeSimpleEscape(char escape) {
    switch (escape) {
      case 'b': return '\b';
      case 'f': return '\f';
      case 'n': return '\n';
      case 'r': return '\r';
      case 't': return '\t';
      default: return escape;  // '"', '\\', '/'
    }
  }

  // Numbers and the literals true, false, null: everything up to a delimiter.
  bool scanScalar() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !isDelimiter(text_[pos_])) ++pos_;
    return pos_ > start;
  }

  static bool isWhitespace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  static bool isDelimiter(char c) { return isWhitespace(c) || c == ',' || c == ']' || c == '}'; }

  void skipWhitespace() {
    while (pos_ < text_.size() && isWhitespace(text_[pos_])) ++pos_;
  }

  bool consume(char c) {
    if (pos_ >= text_.size() || text_[pos_] != c) return false;
    ++pos_;
    return true;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::vector<JsonValueSpan> spans_;
};

}  // namespace

std::vector<JsonValueSpan> scanJsonValues(std::string_view text) { return JsonScanner(text).scan(); }

TextPosition textPositionAt(std::string_view text, std::size_t offset) {
  const std::size_t end = offset < text.size() ? offset : text.size();
  // A byte order mark is invisible in an editor, so it takes no column.
  std::size_t i = text.starts_with(kByteOrderMark) ? kByteOrderMark.size() : 0;
  TextPosition position{1, 1};
  for (; i < end; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == '\n') {
      ++position.line;
      position.column = 1;
    } else if ((byte & 0xC0) != 0x80) {  // not a UTF-8 continuation byte
      ++position.column;
    }
  }
  return position;
}

std::optional<TextPosition> locateJsonPointer(std::string_view text, std::string_view pointer,
                                              JsonLocationTarget target) {
  std::optional<TextPosition> found;
  for (const JsonValueSpan& span : scanJsonValues(text)) {
    if (span.pointer != pointer) continue;
    const bool wantKey = target == JsonLocationTarget::Key && span.keyOffset != std::string_view::npos;
    found = textPositionAt(text, wantKey ? span.keyOffset : span.valueOffset);
  }
  return found;
}

std::string escapeJsonPointerToken(std::string_view token) {
  std::string escaped;
  escaped.reserve(token.size());
  for (const char c : token) {
    if (c == '~') {
      escaped += "~0";
    } else if (c == '/') {
      escaped += "~1";
    } else {
      escaped += c;
    }
  }
  return escaped;
}

std::string unescapeJsonPointerToken(std::string_view token) {
  std::string unescaped;
  unescaped.reserve(token.size());
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (token[i] == '~' && i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1')) {
      unescaped += token[i + 1] == '0' ? '~' : '/';
      ++i;
    } else {
      unescaped += token[i];
    }
  }
  return unescaped;
}

}  // namespace scene_input
