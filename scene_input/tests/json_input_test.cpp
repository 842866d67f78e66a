// The one JSON reader of scene files and glTF files, and the wording of its
// value checks, against cases worked out by hand.
#include "scene_input/json_input.h"

#include <gtest/gtest.h>

namespace scene_input {
namespace {

using namespace lighting;

using Json = nlohmann::ordered_json;

JsonInputError refusal(std::string_view text) {
  try {
    readJsonInput(text, "a test input");
  } catch (const JsonInputError& e) {
    return e;
  }
  ADD_FAILURE() << "read: " << text;
  return JsonInputError("", {}, "");
}

TEST(JsonInput, ARepeatedKeyIsRefusedAtItsSecondKey) {
  const JsonInputError e = refusal("{\"a\": 1,\n \"b\": {\"c\": 2, \"c\": 3}}");
  EXPECT_EQ(e.pointer(), "/b/c");
  EXPECT_EQ(e.where().line, 2);
  EXPECT_EQ(e.where().column, 16);  // the quote of the second "c"
  EXPECT_EQ(e.message(), "duplicate key 'c'; each key may appear once");
}

TEST(JsonInput, TheSameKeyInTwoObjectsIsNoRepeat) {
  EXPECT_EQ(readJsonInput(R"([{"a": 1}, {"a": 2}])", "x")[1]["a"], 2);
}

TEST(JsonInput, NonFiniteLiteralsAreNamedWithTheInputsKind) {
  const JsonInputError e = refusal("{\"a\": [1, -Infinity]}");
  EXPECT_EQ(e.where().line, 1);
  EXPECT_EQ(e.where().column, 11);
  EXPECT_EQ(e.message(), "non-finite numbers (NaN, Infinity) are not allowed in a test input; found '-Infinity'");
}

TEST(JsonInput, ANumberTooLargeForADoubleIsNamedWithItsPointer) {
  const JsonInputError e = refusal("{\"a\": {\"b\": 1e999}}");
  EXPECT_EQ(e.pointer(), "/a/b");
  EXPECT_EQ(e.message(), "non-finite numbers (NaN, Infinity) are not allowed in a test input; 1e999 is too large for a double");
}

TEST(JsonInput, TextThatIsNotJsonSaysWhere) {
  const JsonInputError e = refusal("{\"a\": 1,\n}");
  EXPECT_EQ(e.where().line, 2);
  EXPECT_NE(e.message().find("invalid JSON: syntax error"), std::string::npos) << e.message();
}

TEST(JsonInput, ValueChecksSayWhatWasExpectedAndWhatCame) {
  EXPECT_EQ(numberProblem(Json("x")), "expected a number, got a string");
  EXPECT_EQ(numberProblem(Json(2.0), closed(0, 1)), "expected a number in [0, 1], got 2");
  EXPECT_EQ(numberProblem(Json(0.0), above(0)), "expected a number > 0, got 0");
  EXPECT_EQ(numberProblem(Json(0.5), closed(0, 1)), std::nullopt);
  EXPECT_EQ(integerProblem(Json(2.5), 0, 64), "expected an integer in [0, 64], got 2.5");
  EXPECT_EQ(integerProblem(Json(128.0), 0, 256), std::nullopt);  // JSON has one number type
  EXPECT_EQ(integerProblem(Json(true), 0, 64), "expected an integer in [0, 64], got a boolean");
  EXPECT_EQ(kindProblem(Json::array(), JsonKind::Object), "expected an object, got an array");
  EXPECT_EQ(kindProblem(Json(1), JsonKind::Boolean), "expected true or false, got a number");
  EXPECT_EQ(kindProblem(Json("s"), JsonKind::String), std::nullopt);
}

TEST(JsonInput, BoundsSpellTheirInterval) {
  EXPECT_EQ((NumberBounds{0, true, 180, false}).describe(), "in (0, 180]");
  EXPECT_EQ(atLeast(0.5).describe(), ">= 0.5");
  EXPECT_EQ(kAnyNumber.describe(), "");
}

}  // namespace
}  // namespace scene_input
