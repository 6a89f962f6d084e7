#include "mocap/base/error.h"
#include "mocap/base/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocap {
namespace {

TEST(JsonWriter, WritesNestedValuesWithEscapes)
{
  JsonWriter json(0);
  json.beginObject();
  json.key("name").value("a\"b\\c\n");
  json.key("list").beginArray().value(1).value(0.5).value(std::nan("")).value(true).null().endArray();
  json.key("empty").beginObject().endObject();
  json.endObject();
  EXPECT_EQ(json.str(), R"({"name":"a\"b\\c\n","list":[1,0.5,null,true,null],"empty":{}})");
}

TEST(JsonWriter, MisuseThrows)
{
  JsonWriter json;
  json.beginObject();
  EXPECT_THROW(json.value(1), InvalidArgument);
  EXPECT_THROW((void)json.str(), InvalidArgument);
  EXPECT_THROW(json.endArray(), InvalidArgument);
  EXPECT_EQ(jsonQuote(std::string(1, '\x01')), "\"\\u0001\"");
}

TEST(JsonWriter, NumbersRoundTrip)
{
  JsonWriter json(0);
  const double rate = static_cast<double>(65.053f);  // a float frame rate widened to double
  json.beginArray().value(0.1).value(rate).value(1e-300).endArray();
  const std::string text = json.str();
  EXPECT_EQ(text.rfind("[0.1,", 0), 0u) << text;
  EXPECT_EQ(std::stod(text.substr(5)), rate) << text;
  EXPECT_NE(text.find(",1e-300]"), std::string::npos) << text;
}

} // namespace
} // namespace mocap
