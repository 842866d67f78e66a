// How an error message names the kind of a JSON value ("a number", "an
// object"), for the scene loader and the glTF checks alike; any nlohmann
// json type (ordered or not).
#pragma once

#include <string>

namespace scene_input {

template <typename Json>
std::string describeJsonType(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "a boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "a number";
    case Json::value_t::string: return "a string";
    case Json::value_t::array: return "an array";
    case Json::value_t::object: return "an object";
    default: return "an unsupported value";
  }
}

// The same, with an array's length ("an array of 2 values"), where the
// length is what is wrong.
template <typename Json>
std::string describeJsonTypeAndLength(const Json& value) {
  if (!value.is_array()) return describeJsonType(value);
  return "an array of " + std::to_string(value.size()) + (value.size() == 1 ? " value" : " values");
}

}  // namespace scene_input
