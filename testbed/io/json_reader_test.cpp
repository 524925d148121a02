#include "testbed/io/json_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "testbed/io/json_input.h"
#include "tests/cli_helpers.h"

namespace testbed {
namespace {

using nlohmann::json;

std::string errorOf(const std::function<void()>& read) { return test::inputErrorOf(read).value_or("accepted"); }

// The rule for whole numbers: 3, 3.0 and 3e0 are all 3, in every file the reader reads.
TEST(JsonReader, AWholeNumberIsWholeHoweverWritten) {
  const json document = parseJsonInput(R"({"a": 3, "b": 3.0, "c": 3e0, "d": -0.0, "e": 3.5})", "x.json");
  const JsonField top(document, "x.json");
  EXPECT_EQ(top["a"].integer(0, 10), 3);
  EXPECT_EQ(top["b"].integer(0, 10), 3);
  EXPECT_EQ(top["c"].integer(0, 10), 3);
  EXPECT_EQ(top["d"].integer(0, 10), 0);
  EXPECT_EQ(top["b"].count(), 3u);
  EXPECT_EQ(errorOf([&] { top["e"].integer(0, 10); }), "x.json: e: expected an integer in [0, 10], got 3.5");
  EXPECT_EQ(errorOf([&] { top["e"].count(); }), "x.json: e: expected a non-negative integer, got 3.5");
  EXPECT_EQ(errorOf([&] { top["b"].integer(4, 10); }), "x.json: b: must be an integer in [4, 10], got 3.0");
  EXPECT_EQ(errorOf([&] { JsonField(json(1e300), "x.json", "n").integer(0, 10); }),
            "x.json: n: must be an integer in [0, 10], got 1e+300");
  EXPECT_EQ(errorOf([&] { JsonField(json(-1), "x.json", "n").count(); }),
            "x.json: n: expected a non-negative integer, got -1");
  EXPECT_EQ(JsonField(json(std::uint64_t(1) << 62), "f").count(), std::uint64_t(1) << 62);
}

// A parsed file cannot hold NaN or infinity, but a value built in code can.
TEST(JsonReader, NumbersAreFinite) {
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    const json value = {{"v", bad}};
    EXPECT_EQ(errorOf([&] { JsonField(value, "x.json")["v"].number(); }), "x.json: v: not a finite number");
    EXPECT_NE(errorOf([&] { JsonField(value, "x.json")["v"].integer(0, 1); }), "accepted");
    EXPECT_NE(errorOf([&] { JsonField(value, "x.json")["v"].count(); }), "accepted");
  }
  EXPECT_EQ(errorOf([&] { parseJsonInput(R"({"v": 1e999})", "x.json"); }), "x.json: v: not a finite number");
  EXPECT_EQ(errorOf([&] { JsonField(json("1"), "x.json", "v").number(); }), "x.json: v: expected a number, got \"1\"");
  EXPECT_EQ(errorOf([&] { JsonField(json(true), "x.json", "v").number(); }), "x.json: v: expected a number, got true");
}

TEST(JsonReader, UnknownAndMissingKeysAreRefused) {
  const json value = {{"eye", 1}, {"colour", "red"}};
  const JsonField top(value, "x.json", "camera");
  EXPECT_EQ(errorOf([&] { top.allowKeys({"eye", "target"}); }),
            "x.json: camera.colour: unknown key (allowed here: eye, target)");
  EXPECT_NO_THROW(top.allowKeys({"eye", "colour"}));
  EXPECT_EQ(errorOf([&] { top["target"]; }), "x.json: camera.target: missing required key");
  EXPECT_FALSE(top.find("target"));
  EXPECT_EQ(errorOf([&] { JsonField(json::array(), "x.json", "camera").allowKeys({}); }),
            "x.json: camera: expected a JSON object {...}, got []");
}

// The message names the value's whole key path; a key that is not a plain word is quoted.
TEST(JsonReader, MessagesNameTheNestedPath) {
  const json document = parseJsonInput(R"({"objects": [{}, {}, {"translate": [1, 2], "a b": {"c": "x"}}]})", "scenes/x.json");
  const JsonField object = JsonField(document, "scenes/x.json")["objects"][2];
  EXPECT_EQ(errorOf([&] { object["translate"].numbers<3>(); }),
            "scenes/x.json: objects[2].translate: expected an array of 3 numbers, got [1,2]");
  EXPECT_EQ(errorOf([&] { object["a b"]["c"].number(); }), "scenes/x.json: objects[2][\"a b\"].c: expected a number, got \"x\"");
  EXPECT_EQ(errorOf([&] { object["a b"]["c"].boolean(); }), "scenes/x.json: objects[2][\"a b\"].c: expected true or false, got \"x\"");
  // No file: the path alone; no path: the file alone.
  EXPECT_EQ(errorOf([&] { JsonField(json(1), "", "light.eye").text(); }), "light.eye: expected a string, got 1");
  EXPECT_EQ(errorOf([&] { JsonField(json(1), "x.json").text(); }), "x.json: expected a string, got 1");
}

TEST(JsonReader, FixedLengthArraysAndWords) {
  const json value = {{"v", {1, 2.5, 3}}, {"type", "spot"}, {"bad", "Spot"}};
  const JsonField top(value, "x.json");
  EXPECT_EQ(top["v"].numbers<3>(), (std::array<double, 3>{1, 2.5, 3}));
  EXPECT_EQ(errorOf([&] { top["v"].numbers<2>(); }), "x.json: v: expected an array of 2 numbers, got [1,2.5,3]");
  EXPECT_EQ(top["type"].word({"spot", "directional"}), 0u);
  EXPECT_EQ(errorOf([&] { top["bad"].word({"spot", "directional"}); }),
            "x.json: bad: expected \"spot\" or \"directional\", got \"Spot\"");
  EXPECT_EQ(quotedAlternatives({"16", "24", "32f"}), "\"16\", \"24\" or \"32f\"");
}

}  // namespace
}  // namespace testbed
