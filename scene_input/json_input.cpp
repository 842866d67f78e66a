#include "scene_input/json_input.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <unordered_set>
#include <vector>

namespace scene_input {
namespace {

// nlohmann-json messages start "[json.exception.parse_error.101] parse error at
// line 1, column 8: "; the position is reported separately, so keep the rest.
std::string stripExceptionPrefix(const std::string& what) {
  const std::size_t colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

bool isLiteralChar(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '-' || c == '+'; }

std::string literalAt(std::string_view text, std::size_t start) {
  std::size_t end = start;
  while (end < text.size() && isLiteralChar(text[end])) ++end;
  return std::string(text.substr(start, end - start));
}

// The start of a NaN or Infinity literal around `offset` (where the parser
// gave up), or nullopt. Such text is a common way to write a non-finite
// number, and deserves a clearer message than "invalid literal".
std::optional<std::size_t> nonFiniteLiteralStart(std::string_view text, std::size_t offset) {
  std::size_t start = std::min(offset, text.size());
  while (start > 0 && isLiteralChar(text[start - 1])) --start;
  if (start > 0 && text[start - 1] == '"') return std::nullopt;  // inside an unterminated string
  std::size_t letters = start;
  while (letters < text.size() && (text[letters] == '-' || text[letters] == '+')) ++letters;
  std::string word;
  for (std::size_t i = letters; i < text.size() && word.size() < 3; ++i) {
    word += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
  }
  if (word == "nan" || word == "inf") return start;
  return std::nullopt;
}

// nlohmann-json 3.11 refuses a number that overflows a double (1e999) with
// out_of_range.406, which carries no position; find the number in the text.
std::optional<JsonValueSpan> findOverflowingNumber(std::string_view text) {
  for (JsonValueSpan& span : scanJsonValues(text)) {
    const char first = text[span.valueOffset];
    if (first != '-' && !std::isdigit(static_cast<unsigned char>(first))) continue;
    const std::string number(text.substr(span.valueOffset, span.valueLength));
    if (std::isinf(std::strtod(number.c_str(), nullptr))) return std::move(span);
  }
  return std::nullopt;
}

template <typename Json>
Json parse(std::string_view text, std::string_view kind) {
  const std::string nonFinite = "non-finite numbers (NaN, Infinity) are not allowed in " + std::string(kind);
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const typename Json::parse_error& error) {
    // `byte` is the 1-based index of the last character read.
    const std::size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    if (auto start = nonFiniteLiteralStart(text, offset))
      throw JsonInputError("", textPositionAt(text, *start), nonFinite + "; found '" + literalAt(text, *start) + "'");
    throw JsonInputError("", textPositionAt(text, offset), "invalid JSON: " + stripExceptionPrefix(error.what()));
  } catch (const typename Json::exception& error) {
    if (auto number = findOverflowingNumber(text))
      throw JsonInputError(number->pointer, textPositionAt(text, number->valueOffset),
                           nonFinite + "; " + std::string(text.substr(number->valueOffset, number->valueLength)) +
                               " is too large for a double");
    throw JsonInputError("", {}, "invalid JSON: " + stripExceptionPrefix(error.what()));
  }
}

void rejectDuplicateKeys(std::string_view text) {
  const std::vector<JsonValueSpan> spans = scanJsonValues(text);
  std::unordered_set<std::string_view> seen;  // views into `spans`
  for (const JsonValueSpan& span : spans) {
    if (span.keyOffset == std::string_view::npos || seen.insert(span.pointer).second) continue;
    const std::string_view escapedKey = std::string_view(span.pointer).substr(span.pointer.rfind('/') + 1);
    throw JsonInputError(span.pointer, textPositionAt(text, span.keyOffset),
                         "duplicate key '" + unescapeJsonPointerToken(escapedKey) + "'; each key may appear once");
  }
}

}  // namespace

JsonInputError::JsonInputError(std::string pointer, TextPosition where, std::string message)
    : std::runtime_error(message), pointer_(std::move(pointer)), where_(where), message_(std::move(message)) {}

template <typename Json>
Json readJsonInput(std::string_view text, std::string_view kind) {
  Json document = parse<Json>(text, kind);
  rejectDuplicateKeys(text);
  return document;
}

template nlohmann::ordered_json readJsonInput(std::string_view, std::string_view);
template nlohmann::json readJsonInput(std::string_view, std::string_view);

std::string formatJsonNumber(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string NumberBounds::describe() const {
  const bool hasMin = min > -std::numeric_limits<double>::infinity();
  const bool hasMax = max < std::numeric_limits<double>::infinity();
  if (hasMin && hasMax)
    return std::string("in ") + (minOpen ? "(" : "[") + formatJsonNumber(min) + ", " + formatJsonNumber(max) +
           (maxOpen ? ")" : "]");
  if (hasMin) return (minOpen ? "> " : ">= ") + formatJsonNumber(min);
  if (hasMax) return (maxOpen ? "< " : "<= ") + formatJsonNumber(max);
  return "";
}

}  // namespace scene_input
