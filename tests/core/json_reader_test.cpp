#include "mocap/base/error.h"
#include "mocap/base/json_reader.h"
#include "mocap/base/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace mocap {
namespace {

// The FormatError that parsing `text` raises (a failure is recorded when it parses).
FormatError parseError(const std::string& text)
{
  try {
    (void)parseJson(text, "doc.json");
  } catch (const FormatError& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << text;
  return FormatError("doc.json", "accepted");
}

TEST(JsonReader, ReadsEveryKindOfValue)
{
  const JsonValue root = parseJson(
      R"( {"b": [1, -2.5, 3e2, 1E-3, 0, 18446744073709551615], "a": {"t": true, "f": false, "n": null},
          "s": "q\"\\\/\b\f\n\r\t\u00e9\u20ac\ud83d\ude00", "empty": [], "none": {}} )",
      "doc.json");
  ASSERT_TRUE(root.isObject());
  // Keys are kept sorted.
  std::string keys;
  for (const auto& [key, value] : root.object("root"))
    keys += key + ",";
  EXPECT_EQ(keys, "a,b,empty,none,s,");

  const auto& numbers = root.find("b", "root")->array("b");
  ASSERT_EQ(numbers.size(), 6u);
  EXPECT_EQ(numbers[0].number("b"), 1.0);
  EXPECT_EQ(numbers[1].number("b"), -2.5);
  EXPECT_EQ(numbers[2].number("b"), 300.0);
  EXPECT_EQ(numbers[3].number("b"), 1e-3);
  EXPECT_EQ(numbers[4].number("b"), 0.0);
  EXPECT_EQ(numbers[5].number("b"), 18446744073709551615.0);

  const JsonValue& flags = *root.find("a", "root");
  EXPECT_EQ(flags.find("t", "a")->type(), JsonValue::Type::Boolean);
  EXPECT_EQ(flags.find("f", "a")->type(), JsonValue::Type::Boolean);
  EXPECT_TRUE(flags.find("n", "a")->isNull());
  EXPECT_EQ(flags.find("missing", "a"), nullptr);

  EXPECT_EQ(root.find("s", "root")->string("s"), "q\"\\/\b\f\n\r\t\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80");
  EXPECT_TRUE(root.find("empty", "root")->array("empty").empty());
  EXPECT_TRUE(root.find("none", "root")->object("none").empty());

  // Zero keeps its sign, as a double must (the writer writes -0.0 as "-0").
  const auto firstNumber = [](const JsonValue& v) {
    return v.isArray() ? v.array("x")[0].number("x") : v.isObject() ? v.find("a", "x")->number("x") : v.number("x");
  };
  for (const char* text : {"-0", "[-0]", "[ -0 ,0]", "{\"a\":-0}", "-0.0", "-0e0"})
    EXPECT_TRUE(std::signbit(firstNumber(parseJson(text, "doc.json")))) << text;
  for (const char* text : {"0", "[0]", "[ 0 ,-0]", "{\"a\":0}", "0.0", "[10]", "{\"b\":-0,\"a\":0}"})
    EXPECT_FALSE(std::signbit(firstNumber(parseJson(text, "doc.json")))) << text;

  // A document may be a scalar.
  EXPECT_EQ(parseJson("42", "doc.json").number("x"), 42.0);
  EXPECT_EQ(parseJson(" \"x\"\n", "doc.json").string("x"), "x");
  EXPECT_TRUE(parseJson("null", "doc.json").isNull());
}

TEST(JsonReader, WrongTypeNamesTheValue)
{
  const JsonValue root = parseJson(R"({"a": "text"})", "doc.json");
  try {
    (void)root.find("a", "root")->number("the a field");
    FAIL() << "a string read as a number";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()), "the a field must be a number");
  }
  EXPECT_THROW((void)root.array("root"), InvalidArgument);
  EXPECT_THROW((void)root.find("a", "root")->find("b", "a"), InvalidArgument);
}

TEST(JsonReader, RefusesInvalidDocumentsAtTheOffendingByte)
{
  struct Case
  {
    std::string text;
    std::int64_t offset;
    const char* message;
  };
  const Case cases[] = {
      {".5", 0, "invalid literal"},
      {"1.", 2, "expected digit after '.'"},
      {"[1., 2]", 3, "expected digit after '.'"},
      {"01", 1, "unexpected text after the JSON value"},
      {"-", 1, "expected digit after '-'"},
      {"[-]", 2, "expected digit after '-'"},
      {"\"\\ud800\"", 7, "surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF"},
      {"\"\\udc00\"", 6, "surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF"},
      {"\"a\xFF\"", 2, "ill-formed UTF-8"},
      {"\"a\xE2\x82\"", 4, "ill-formed UTF-8"},
      {"\"\xED\xA0\x80\"", 2, "ill-formed UTF-8"},  // a surrogate encoded as UTF-8 (CESU-8)
      {"\"\xC0\xAF\"", 1, "ill-formed UTF-8"},      // an overlong encoding of '/'
      {"\"a\tb\"", 2, "control character"},
      {"[1,]", 3, "unexpected ']'"},
      {R"({"a": 1,})", 8, "unexpected '}'"},
      {"{} x", 3, "unexpected text after the JSON value"},
      {"[1] [2]", 4, "unexpected text after the JSON value"},
      {R"({"a": 1, "a": 2})", 9, "repeated key \"a\""},
      {R"({"a\"b": 1, "a\"b": 2})", 12, "repeated key \"a\"b\""},
      {R"({"x": {"k": 1, "k": 1}})", 15, "repeated key \"k\""},
      {"", 0, "unexpected end of JSON"},
      {R"({"a": [1)", 8, "unexpected end of JSON"},
      {"\"abc", 4, "unexpected end of JSON"},
      {"1e400", 4, "number overflow"},
      {"NaN", 0, "invalid literal"},
      {"[1, /* note */ 2]", 4, "invalid literal"},
      {"{'a': 1}", 1, "invalid literal"},
      {"tru", 3, "invalid literal"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const FormatError e = parseError(c.text);
    EXPECT_EQ(e.file(), "doc.json");
    EXPECT_EQ(e.offset(), c.offset) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
    // The message is ours alone: no nlohmann exception id or line/column prefix.
    EXPECT_EQ(std::string(e.what()).find("json.exception"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("doc.json: ", 0), 0u) << e.what();
    const std::string tail = " at byte " + std::to_string(c.offset);
    EXPECT_EQ(std::string(e.what()).substr(std::string(e.what()).size() - tail.size()), tail) << e.what();
  }
}

TEST(JsonReader, RefusesNestingDeeperThan256)
{
  const auto nested = [](std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  EXPECT_TRUE(parseJson(nested(256), "doc.json").isArray());
  const FormatError arrays = parseError(nested(257));
  EXPECT_EQ(arrays.offset(), 256);
  EXPECT_NE(std::string(arrays.what()).find("nested too deeply"), std::string::npos) << arrays.what();

  std::string objects;
  for (int i = 0; i < 257; ++i)
    objects += "{\"k\": ";
  objects += "1" + std::string(257, '}');
  const FormatError e = parseError(objects);
  EXPECT_EQ(e.offset(), 256 * 6);
  EXPECT_NE(std::string(e.what()).find("nested too deeply"), std::string::npos) << e.what();

  // Far deeper input is refused as quickly, without exhausting the stack.
  EXPECT_EQ(parseError(nested(1000000)).offset(), 256);
}

TEST(JsonReader, ReadsBackWhatTheWriterWrote)
{
  const std::string texts[] = {"plain", "naïve café", "日本語", "\xF0\x9F\x98\x80 emoji", "quote \" backslash \\",
                               "control \x01\x1F\b\f\n\r\t", "slash / and \x7F"};
  const double numbers[] = {0.0, -0.0, 1.0, -2.5, 0.1, 1e-300, 1.7976931348623157e308, 5e-324,
                            static_cast<double>(65.053f), 123456789012345.0};
  for (const int indent : {0, 2}) {
    JsonWriter json(indent);
    json.beginObject();
    json.key("texts").beginArray();
    for (const std::string& text : texts)
      json.value(text);
    json.endArray();
    json.key("numbers").beginArray();
    for (const double number : numbers)
      json.value(number);
    json.endArray();
    json.key("count").value(std::int64_t{-9007199254740991});
    json.key("flag").value(true);
    json.key("nothing").null();
    json.key("ключ").value("значение");
    json.endObject();

    const JsonValue back = parseJson(json.str(), "written.json");
    const auto& readTexts = back.find("texts", "root")->array("texts");
    ASSERT_EQ(readTexts.size(), std::size(texts));
    for (std::size_t i = 0; i < readTexts.size(); ++i)
      EXPECT_EQ(readTexts[i].string("text"), texts[i]);
    const auto& readNumbers = back.find("numbers", "root")->array("numbers");
    ASSERT_EQ(readNumbers.size(), std::size(numbers));
    for (std::size_t i = 0; i < readNumbers.size(); ++i) {
      const double read = readNumbers[i].number("number");
      EXPECT_EQ(std::memcmp(&read, &numbers[i], sizeof read), 0) << numbers[i];  // bit for bit, zero's sign too
    }
    EXPECT_EQ(back.find("count", "root")->number("count"), -9007199254740991.0);
    EXPECT_EQ(back.find("flag", "root")->type(), JsonValue::Type::Boolean);
    EXPECT_TRUE(back.find("nothing", "root")->isNull());
    EXPECT_EQ(back.find("ключ", "root")->string("ключ"), "значение");
  }
}

TEST(JsonReader, WriterReplacesIllFormedUtf8SoTheOutputStaysValid)
{
  const std::string replacement = "\xEF\xBF\xBD";  // U+FFFD
  const std::pair<std::string, std::string> cases[] = {
      {"a\xFF" "b", "a" + replacement + "b"},                 // a byte that never starts UTF-8
      {"Lat\xE9ral", "Lat" + replacement + "ral"},            // Latin-1, as C3D labels often are
      {"\xE2\x82" "c", replacement + "c"},                    // a truncated sequence
      {"end\xE2\x82", "end" + replacement},                   // truncated at the end
      {"\xED\xA0\x80", replacement + replacement + replacement},  // a UTF-8-encoded surrogate
      {"\xC0\xAF", replacement + replacement},                // an overlong '/'
      {"ok \xC3\xA9", "ok \xC3\xA9"},                         // well-formed UTF-8 is kept
  };
  for (const auto& [input, expected] : cases) {
    SCOPED_TRACE(input);
    EXPECT_EQ(jsonQuote(input), "\"" + expected + "\"");
    JsonWriter json(0);
    json.beginObject().key(input).value(input).endObject();
    const JsonValue back = parseJson(json.str(), "written.json");
    ASSERT_EQ(back.object("root").size(), 1u);
    EXPECT_EQ(back.object("root").begin()->first, expected);
    EXPECT_EQ(back.object("root").begin()->second.string("value"), expected);
  }
}

} // namespace
} // namespace mocap
