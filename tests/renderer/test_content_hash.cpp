// The content hash that tells ranks' scene files apart: FNV-1a 64 as
// published, incremental, and never blind to a change confined to one byte.

#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "renderer/content_hash.h"

using namespace raylab;

TEST_CASE("contentHash: the published FNV-1a 64 values") {
    CHECK(contentHash("") == 0xcbf29ce484222325ull);  // the offset basis
    CHECK(contentHash("a") == 0xaf63dc4c8601ec8cull);
    CHECK(contentHash("foobar") == 0x85944171f73967e8ull);
}

TEST_CASE("ContentHash: pieces hash like the whole, numbers as 8 little-endian bytes") {
    CHECK(ContentHash().add("foo").add("bar").value() == contentHash("foobar"));
    const std::string le("\x08\x07\x06\x05\x04\x03\x02\x01", 8);
    CHECK(ContentHash().addNumber(0x0102030405060708ull).value() == contentHash(le));
    // A length between two strings keeps their boundary.
    CHECK(ContentHash().addNumber(2).add("ab").addNumber(1).add("c").value() !=
          ContentHash().addNumber(1).add("a").addNumber(2).add("bc").value());
}

TEST_CASE("ContentHash: every change of a single byte changes the hash") {
    std::string text;
    for (int i = 0; i < 64; ++i) text += char('a' + i % 26);
    const uint64_t original = contentHash(text);
    int unchanged = 0;
    for (size_t at = 0; at < text.size(); ++at)
        for (int value = 0; value < 256; ++value) {
            if (char(value) == text[at]) continue;
            std::string changed = text;
            changed[at] = char(value);
            unchanged += contentHash(changed) == original;
        }
    CHECK(unchanged == 0);
}
