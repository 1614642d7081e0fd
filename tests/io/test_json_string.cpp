// jsonString, the one JSON string writer (--stats, benchmark and accuracy
// tables): exact escapes, and what it writes reads back through parseJson.
#include <doctest/doctest.h>

#include <string>

#include "renderer/io/json.h"
#include "renderer/io/json_string.h"

using namespace raylab;

TEST_CASE("jsonString: quotes, backslashes and control characters are escaped") {
    CHECK(jsonString("") == "\"\"");
    CHECK(jsonString("plain") == "\"plain\"");
    CHECK(jsonString("a\"b\\c") == "\"a\\\"b\\\\c\"");
    CHECK(jsonString("\n\r\t\b\f") == "\"\\n\\r\\t\\b\\f\"");
    CHECK(jsonString(std::string("\x00\x01\x1f", 3)) == "\"\\u0000\\u0001\\u001f\"");
    CHECK(jsonString("\x7f/") == "\"\x7f/\"");                       // DEL and '/' need no escape
    CHECK(jsonString("caf\xc3\xa9 \xe2\x82\xac") == "\"caf\xc3\xa9 \xe2\x82\xac\"");  // UTF-8 as is
    // Appended after what the output holds; plain runs between escapes kept.
    std::string out = "[";
    appendJsonString(out, "ab\"cd\nef");
    appendJsonString(out, "");
    CHECK(out == "[\"ab\\\"cd\\nef\"\"\"");
}

TEST_CASE("jsonString: every ASCII character and some UTF-8 read back unchanged") {
    std::string all;
    for (int c = 0; c < 128; ++c) all += char(c);
    all += "\xc3\xa9\xe2\x82\xac\xf0\x9f\x99\x82";
    const JsonValue v = parseJson("{\"s\": " + jsonString(all) + "}", "test.json");
    REQUIRE(v.find("s"));
    CHECK(v.find("s")->asString() == all);
}
