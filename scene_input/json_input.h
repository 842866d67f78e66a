// The one JSON reader of lightcts's inputs: scene files and the JSON of glTF
// files. Reading refuses, with the JSON pointer and the line and column of the
// place: text that is not JSON; NaN and Infinity literals and numbers too
// large for a double (the model has no non-finite number); and a key that
// repeats within an object (RFC 8259 leaves repeats to the parser, and
// nlohmann-json would keep the last silently: a file that says "range" twice
// is ambiguous). The checks of a value's type and range, with the wording
// every input error uses ("expected a number in [0, 1], got 2"), are here too,
// so the scene format and the glTF checks say the same thing the same way.
#pragma once

#include "scene_input/json_describe.h"
#include "scene_input/json_locations.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace scene_input {

// Where an input's JSON is wrong, and why. `where` is {0, 0} when the text
// gives no place (an error of the parser without a position).
class JsonInputError : public std::runtime_error {
 public:
  JsonInputError(std::string pointer, TextPosition where, std::string message);
  const std::string& pointer() const { return pointer_; }
  TextPosition where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string pointer_;
  TextPosition where_;
  std::string message_;
};

// `kind` names the input in the message of a non-finite number ("a scene",
// "a glTF file"). Throws JsonInputError. Either JSON type: a scene keeps its
// keys' order (the first unknown key is named), glTF's checks need none.
template <typename Json = nlohmann::ordered_json>
Json readJsonInput(std::string_view text, std::string_view kind);
extern template nlohmann::ordered_json readJsonInput(std::string_view, std::string_view);
extern template nlohmann::json readJsonInput(std::string_view, std::string_view);

// The shortest text that reads back as `value` ("0.1", "1e+999" never: the
// model's numbers are finite).
std::string formatJsonNumber(double value);

// An interval of allowed numbers, and how a message spells it ("> 0", "in (0, 180]").
struct NumberBounds {
  double min = -std::numeric_limits<double>::infinity();
  bool minOpen = false;
  double max = std::numeric_limits<double>::infinity();
  bool maxOpen = false;

  bool contains(double v) const {
    const bool aboveMin = minOpen ? v > min : v >= min;
    const bool belowMax = maxOpen ? v < max : v <= max;
    return aboveMin && belowMax;
  }
  std::string describe() const;
};

constexpr NumberBounds kAnyNumber{};
constexpr NumberBounds above(double min) { return {min, true, std::numeric_limits<double>::infinity(), false}; }
constexpr NumberBounds atLeast(double min) { return {min, false, std::numeric_limits<double>::infinity(), false}; }
constexpr NumberBounds closed(double min, double max) { return {min, false, max, false}; }

// What is wrong with a value, in the words of an input error, or nullopt when
// it is what is expected. The caller says where (its pointer and position).
template <typename Json>
std::optional<std::string> numberProblem(const Json& value, const NumberBounds& bounds = kAnyNumber) {
  if (!value.is_number()) return "expected a number, got " + describeJsonType(value);
  const double v = value.template get<double>();
  // nlohmann-json 3.11.2 already refuses 1e999 while reading; this guards
  // versions that turn it into infinity.
  if (!std::isfinite(v)) return "expected a finite number, got " + formatJsonNumber(v) + " (non-finite numbers are not allowed)";
  if (!bounds.contains(v)) return "expected a number " + bounds.describe() + ", got " + formatJsonNumber(v);
  return std::nullopt;
}

// JSON has one number type, so 128.0 counts as an integer (as in JSON
// Schema); 1.5 does not.
template <typename Json>
std::optional<std::string> integerProblem(const Json& value, long long min, long long max) {
  const std::string expected = "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!value.is_number()) return expected + ", got " + describeJsonType(value);
  const double v = value.template get<double>();
  if (!std::isfinite(v) || std::trunc(v) != v || v < double(min) || v > double(max))
    return expected + ", got " + formatJsonNumber(v);
  return std::nullopt;
}

enum class JsonKind { Object, Array, Boolean, String };

template <typename Json>
std::optional<std::string> kindProblem(const Json& value, JsonKind kind) {
  const bool matches = kind == JsonKind::Object    ? value.is_object()
                       : kind == JsonKind::Array   ? value.is_array()
                       : kind == JsonKind::Boolean ? value.is_boolean()
                                                   : value.is_string();
  if (matches) return std::nullopt;
  const char* expected = kind == JsonKind::Object    ? "an object"
                         : kind == JsonKind::Array   ? "an array"
                         : kind == JsonKind::Boolean ? "true or false"
                                                     : "a string";
  return std::string("expected ") + expected + ", got " + describeJsonType(value);
}

}  // namespace scene_input
