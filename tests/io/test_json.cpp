// The JSON reader: values, source lines, comments, and every rejection with
// the line it is reported on.
#include <doctest/doctest.h>

#include <string>

#include "renderer/io/errors.h"
#include "renderer/io/json.h"

using namespace raylab;

namespace {

/// The InputError a parse throws (empty, line 0, when it does not throw).
struct ParseFailure {
    std::string file;
    int line = 0;
    std::string message;
};

ParseFailure failureOf(const std::string& text) {
    try {
        parseJson(text, "t.json");
    } catch (const InputError& e) {
        return {e.file(), e.line(), e.what()};
    }
    return {};
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace

TEST_CASE("json: scalars, arrays and objects") {
    const JsonValue v = parseJson(
        R"({"a": 1, "b": [true, false, null], "c": "x", "d": {"e": -2.5e2}, "f": []})", "t.json");
    REQUIRE(v.isObject());
    REQUIRE(v.size() == 5);
    CHECK(v.key(0) == "a");
    CHECK(v.key(4) == "f");
    CHECK(v.find("a")->asNumber() == 1);
    const JsonValue& b = *v.find("b");
    REQUIRE(b.isArray());
    REQUIRE(b.size() == 3);
    CHECK(b.at(0).asBool() == true);
    CHECK(b.at(1).asBool() == false);
    CHECK(b.at(2).isNull());
    CHECK(v.find("c")->asString() == "x");
    CHECK(v.find("d")->find("e")->asNumber() == -250.0);  // -2.5 * 10^2
    CHECK(v.find("f")->isArray());
    CHECK(v.find("f")->size() == 0);
    CHECK(v.find("missing") == nullptr);
    CHECK(b.find("a") == nullptr);  // not an object
    CHECK(std::string(v.typeName()) == "object");
}

TEST_CASE("json: numbers follow the JSON grammar") {
    CHECK(parseJson("0", "t").asNumber() == 0);
    CHECK(parseJson("-0.125", "t").asNumber() == -0.125);
    CHECK(parseJson("1E+2", "t").asNumber() == 100);
    CHECK(parseJson("12e-1", "t").asNumber() == 1.2);
    // Underflow rounds to zero rather than failing: it is not out of range.
    CHECK(parseJson("1e-400", "t").asNumber() == 0);
    for (const char* bad : {"01", "1.", ".5", "+1", "1e", "-", "1.2.3", "0x10", "1e+"})
        CHECK_MESSAGE(contains(failureOf(bad).message, "invalid number"), bad);
}

TEST_CASE("json: every value records the line it starts on") {
    const std::string text =
        "{\n"                   // line 1
        "  \"a\": 1,\n"         // line 2
        "  \"b\": [\n"          // line 3
        "    2,\n"              // line 4
        "    {\"c\": \"x\"}\n"  // line 5
        "  ],\n"                // line 6
        "\r\n"                  // line 7 (CRLF counts once)
        "  \"d\":\n"            // line 8
        "    true\n"            // line 9
        "}\n";
    const JsonValue v = parseJson(text, "t.json");
    CHECK(v.line() == 1);
    CHECK(v.find("a")->line() == 2);
    CHECK(v.keyLine(0) == 2);
    CHECK(v.find("b")->line() == 3);
    CHECK(v.find("b")->at(0).line() == 4);
    CHECK(v.find("b")->at(1).line() == 5);
    CHECK(v.find("b")->at(1).find("c")->line() == 5);
    CHECK(v.keyLine(2) == 8);
    CHECK(v.find("d")->line() == 9);
}

TEST_CASE("json: comments are whitespace and keep line numbers right") {
    const std::string text =
        "// leading comment\n"       // 1
        "{ /* block\n"               // 2
        "     spanning lines */\n"   // 3
        "  \"a\": 1, // trailing\n"  // 4
        "  /* x */ \"b\": 2\n"       // 5
        "}\n"                        // 6
        "// after\n";                // 7
    const JsonValue v = parseJson(text, "t.json");
    CHECK(v.find("a")->asNumber() == 1);
    CHECK(v.find("a")->line() == 4);
    CHECK(v.find("b")->line() == 5);
    // A comment-only file is as empty as an empty one.
    CHECK(contains(failureOf("// nothing\n/* here */").message, "empty file"));
    const ParseFailure open = failureOf("{\n\"a\": 1 /* never\nclosed\n");
    CHECK(open.line == 2);
    CHECK(contains(open.message, "unterminated /* comment"));
}

TEST_CASE("json: strings, escapes and UTF-8") {
    CHECK(parseJson(R"("a\"b\\c\/d\n\t")", "t").asString() == "a\"b\\c/d\n\t");
    // U+00E9 is C3 A9 in UTF-8; U+1F600 is the surrogate pair D83D DE00 and F0 9F 98 80.
    CHECK(parseJson(R"("\u00e9")", "t").asString() == "\xC3\xA9");
    CHECK(parseJson(R"("\uD83D\uDE00")", "t").asString() == "\xF0\x9F\x98\x80");
    // Raw UTF-8 passes through unchanged.
    CHECK(parseJson("\"gr\xC3\xBC\xC3\x9F\"", "t").asString() == "gr\xC3\xBC\xC3\x9F");
    CHECK(contains(failureOf(R"("\uD83D")").message, "lone UTF-16 high surrogate"));
    CHECK(contains(failureOf(R"("\uDE00")").message, "lone UTF-16 low surrogate"));
    CHECK(contains(failureOf(R"("\u12G4")").message, "invalid \\u escape"));
    CHECK(contains(failureOf(R"("\q")").message, "invalid escape"));
    CHECK(contains(failureOf("\"\xC3\"").message, "invalid UTF-8"));          // truncated sequence
    CHECK(contains(failureOf("\"\xC0\xAF\"").message, "invalid UTF-8"));      // overlong '/'
    CHECK(contains(failureOf("\"\xED\xA0\x80\"").message, "invalid UTF-8"));  // surrogate
    CHECK(contains(failureOf("\"a\tb\"").message, "control character"));
    CHECK(contains(failureOf("'single'").message, "double quotes"));
}

TEST_CASE("json: byte-order marks and NUL bytes") {
    // A UTF-8 BOM is skipped.
    CHECK(parseJson("\xEF\xBB\xBF{\"a\": 1}", "t").find("a")->asNumber() == 1);
    const ParseFailure utf16le = failureOf(std::string("\xFF\xFE{\0\"\0", 6));
    CHECK(utf16le.line == 1);
    CHECK(contains(utf16le.message, "UTF-16"));
    CHECK(contains(failureOf("\xFE\xFF\0{").message, "UTF-16"));
    const ParseFailure nul = failureOf(std::string("{\n\"a\":\n1\0}", 10));
    CHECK(nul.line == 3);
    CHECK(contains(nul.message, "NUL byte"));
}

TEST_CASE("json: syntax errors carry file and line") {
    ParseFailure f = failureOf("[1,\n 2,\n]");
    CHECK(f.file == "t.json");
    CHECK(f.line == 3);
    CHECK(contains(f.message, "trailing comma"));

    f = failureOf("{\"a\": 1,\n\n}");
    CHECK(f.line == 3);
    CHECK(contains(f.message, "trailing comma"));

    f = failureOf("{\"a\": 1\n \"b\": 2}");
    CHECK(f.line == 2);
    CHECK(contains(f.message, "expected ',' or '}'"));

    f = failureOf("[1 2]");
    CHECK(contains(f.message, "expected ',' or ']'"));

    f = failureOf("{\"a\" 1}");
    CHECK(contains(f.message, "expected ':'"));

    f = failureOf("{a: 1}");
    CHECK(contains(f.message, "string key"));

    f = failureOf("{\n\"a\": \"open\n}");
    CHECK(f.line == 2);
    CHECK(contains(f.message, "unterminated string"));

    f = failureOf("[1,\n[2,\n");
    CHECK(f.line == 3);
    CHECK(contains(f.message, "end of input"));

    f = failureOf("{\"x\": tru}");
    CHECK(contains(f.message, "invalid literal 'tru'"));

    f = failureOf("[NaN]");
    CHECK(contains(f.message, "no NaN"));

    f = failureOf("[Infinity]");
    CHECK(contains(f.message, "no NaN or infinity"));
}

TEST_CASE("json: empty input and trailing garbage") {
    CHECK(contains(failureOf("").message, "empty file"));
    CHECK(contains(failureOf(" \n\t\n").message, "empty file"));
    const ParseFailure f = failureOf("{\"a\": 1}\n\n}");
    CHECK(f.line == 3);
    CHECK(contains(f.message, "after the end of the JSON value"));
    CHECK(contains(failureOf("1 2").message, "after the end"));
    // Trailing whitespace and comments are fine.
    CHECK(parseJson("[1] \n // done\n", "t").size() == 1);
}

TEST_CASE("json: out-of-range numbers are rejected") {
    const ParseFailure f = failureOf("{\n\"r\": 1e400\n}");
    CHECK(f.line == 2);
    CHECK(contains(f.message, "number out of range"));
    CHECK(contains(failureOf("-1e309").message, "number out of range"));
    // The largest finite double is in range.
    CHECK(parseJson("1.7976931348623157e308", "t").asNumber() == 1.7976931348623157e308);
}

TEST_CASE("json: duplicate keys are rejected") {
    const ParseFailure f = failureOf("{\n\"a\": 1,\n\"b\": 2,\n\"a\": 3\n}");
    CHECK(f.line == 4);
    CHECK(contains(f.message, "duplicate key 'a'"));
    CHECK(contains(f.message, "first defined on line 2"));
    // The same key in different objects is fine.
    CHECK(parseJson(R"([{"a": 1}, {"a": 2}])", "t").size() == 2);
}

TEST_CASE("json: nesting depth is limited, not a stack overflow") {
    auto nested = [](int depth) {
        return std::string(size_t(depth), '[') + std::string(size_t(depth), ']');
    };
    CHECK_NOTHROW(parseJson(nested(kMaxJsonDepth), "t"));
    CHECK(contains(failureOf(nested(kMaxJsonDepth + 1)).message, "nesting deeper than 256"));
    // Far beyond the limit: rejected at the limit, long before the stack runs out.
    CHECK(contains(failureOf(std::string(1000000, '[')).message, "nesting deeper"));
    std::string objects;
    for (int i = 0; i <= kMaxJsonDepth; ++i) objects += "{\"k\":";
    CHECK(contains(failureOf(objects).message, "nesting deeper"));
}

TEST_CASE("json: wrong-type access is a logic error, not a silent default") {
    const JsonValue v = parseJson("[1]", "t");
    CHECK_THROWS_AS(v.asNumber(), std::logic_error);
    CHECK_THROWS_AS(v.at(0).asString(), std::logic_error);
    CHECK_THROWS_AS(v.at(0).asBool(), std::logic_error);
    CHECK(v.at(0).asNumber() == 1);
}
