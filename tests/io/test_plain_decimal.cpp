// The scene readers' numbers: plain decimals ("%f", nearly every number an
// exporter writes) are read by Clinger's fast path (plain_decimal.h), every
// other form by from_chars. parseNumber (OBJ, MTL) and the NFF reader must
// give the same double, bit for bit, and refuse the same tokens as with
// from_chars alone: checked on hand-picked edge cases and two million random
// tokens (plainDecimal directly, and parseNumber), and on an NFF file.

#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "geometry/sphere.h"
#include "renderer/io/errors.h"
#include "renderer/io/plain_decimal.h"
#include "renderer/io/scene_loader.h"
#include "renderer/io/wavefront_text.h"
#include "renderer/sampler.h"
#include "renderer/scene.h"

using namespace raylab;

namespace {

/// What parseNumber gave before the fast path: from_chars alone, with its
/// rules ('+' taken, NaN and Inf and overflow refused, underflow to 0).
std::optional<double> reference(const std::string& token) {
    const char* first = token.data();
    const char* last = first + token.size();
    if (first < last && *first == '+' && first + 1 < last && first[1] != '-') ++first;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ptr != last || token.empty()) return std::nullopt;
    if (ec == std::errc::result_out_of_range) {
        const double approx = std::strtod(token.c_str(), nullptr);
        if (!(std::fabs(approx) < 1.0)) return std::nullopt;
        return approx;
    }
    if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    return v;
}

bool sameResult(const std::optional<double>& a, const std::optional<double>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || std::memcmp(&*a, &*b, sizeof(double)) == 0;  // -0 is not 0
}

void check(const std::string& token) {
    CAPTURE(token);
    CHECK(sameResult(parseNumber(token), reference(token)));
}

}  // namespace

TEST_CASE("parseNumber: plain decimals, hand-picked, against from_chars") {
    for (const char* t :
         {"0", "-0", "0.0", "-0.000000", "+0.5", "1", "-1", "12.345678", "-0.123456", "0.1", "0.3",
          "0.7", "123456789012345", "12345678901234.5", "1234567890123456", "0.000000000000001",
          "0.0000000000000001", "999999999999999", "9007199254740993", "4.35", "2.675",
          "0.1000000000000000055511151231257827", "1.", ".5", "-.5", "-", "+", "", ".", "1e5",
          "1E-3", "0x10", "1.2.3", "--1", "+-1", "-+1", "1-", "nan", "inf", "-inf", "1e400",
          "1e-400", " 1", "1 ", "00000000000000012", "0000000.1", "7.000000", "-3.141593"})
        check(t);
    // Values with an exact midpoint between two doubles in their decimal:
    // the division must round to even exactly as from_chars does.
    check("9007199254740.9921875");  // 20 digits: from_chars' path
    check("0.500000000000000");
    CHECK(parseNumber("12.345678").value() == 12.345678);
    CHECK(std::signbit(parseNumber("-0.000000").value()));
}

TEST_CASE("parseNumber: two million random tokens give from_chars' doubles") {
    Pcg32 rng(20261202, 7);
    const char alphabet[] = "0123456789012345678901234567890123456789.-+e";
    for (int n = 0; n < 2000000; ++n) {
        std::string t;
        switch (rng.next() % 3) {
            case 0: {  // "%f"-like: sign, up to 9 integer digits, up to 12 decimals
                if (rng.next() % 2) t += '-';
                const int a = 1 + int(rng.next() % 9), b = int(rng.next() % 13);
                for (int k = 0; k < a; ++k) t += char('0' + rng.next() % 10);
                if (b > 0) {
                    t += '.';
                    for (int k = 0; k < b; ++k) t += char('0' + rng.next() % 10);
                }
                break;
            }
            case 1: {  // long digit strings around the 15-digit limit
                if (rng.next() % 2) t += '-';
                const int a = 1 + int(rng.next() % 18);
                const int dot = int(rng.next() % (a + 1));
                for (int k = 0; k < a; ++k) {
                    if (k == dot && k > 0) t += '.';
                    t += char('0' + rng.next() % 10);
                }
                break;
            }
            default: {  // anything from the alphabet
                const int len = int(rng.next() % 8);
                for (int k = 0; k < len; ++k) t += alphabet[rng.next() % (sizeof alphabet - 1)];
            }
        }
        const std::optional<double> got = parseNumber(t), want = reference(t);
        if (!sameResult(got, want)) {
            CAPTURE(t);
            FAIL_CHECK("parseNumber differs from from_chars");
        }
        // The fast path alone: a value only for plain decimals, then from_chars'.
        const std::optional<double> plain = plainDecimal(t.data(), t.data() + t.size());
        if (plain && !sameResult(plain, want)) {
            CAPTURE(t);
            FAIL_CHECK("plainDecimal differs from from_chars");
        }
    }
}

TEST_CASE("NFF numbers: plain, signed, exponent and long forms read as from_chars reads them") {
    // A sphere whose centre and radius take every path: the fast one
    // ("-0.250000", "+1.5"), and from_chars ("1e-1", ".75", 17 digits).
    const Scene scene = loadNffScene(
        "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 8 8\n"
        "f 1 1 1 1 0 1 0 0\ns -0.250000 +1.5 1e-1 .75\n"
        "s 0.12345678901234567 -7.000001 3 2.5\n",
        "numbers.nff");
    REQUIRE(scene.objects.size() == 2);
    const auto bitsEqual = [](const std::string& token, double value) {
        CAPTURE(token);
        const std::optional<double> want = reference(token);
        REQUIRE(want);
        CHECK(std::memcmp(&*want, &value, sizeof value) == 0);
    };
    const auto* a = dynamic_cast<const Sphere*>(scene.objects[0].shape.get());
    const auto* b = dynamic_cast<const Sphere*>(scene.objects[1].shape.get());
    REQUIRE(a);
    REQUIRE(b);
    bitsEqual("-0.250000", a->centre().x);
    bitsEqual("+1.5", a->centre().y);
    bitsEqual("1e-1", a->centre().z);
    bitsEqual(".75", a->radius());
    bitsEqual("0.12345678901234567", b->centre().x);
    bitsEqual("-7.000001", b->centre().y);
    bitsEqual("2.5", b->radius());
}

TEST_CASE("NFF numbers: random tokens and separators, every value as from_chars reads it") {
    // The reader takes a plain decimal in one pass with its token; any other
    // form goes through from_chars. Spheres whose four numbers are random
    // tokens of every valid form, separated by any whitespace, '#' comments
    // and line breaks, the last one ending the file: each value bit for bit
    // as from_chars gives it, each count error on the line of the last
    // number read.
    Pcg32 rng(20261206, 11);
    const char* const separators[] = {" ", "\t", "\n", "  \r\n", "\f", "\v", "#c 1.5\n", "\n\n"};
    const auto randomToken = [&] {
        std::string t;
        switch (rng.next() % 4) {
            case 0:  // "%f"-like
                if (rng.next() % 2) t += '-';
                for (int k = 0, a = 1 + int(rng.next() % 9); k < a; ++k) t += char('0' + rng.next() % 10);
                if (rng.next() % 4) {
                    t += '.';
                    for (int k = 0, b = 1 + int(rng.next() % 9); k < b; ++k) t += char('0' + rng.next() % 10);
                }
                break;
            case 1: {  // around the 15-digit limit
                if (rng.next() % 2) t += '-';
                const int a = 1 + int(rng.next() % 18), dot = int(rng.next() % (a + 1));
                for (int k = 0; k < a; ++k) {
                    if (k == dot && k > 0) t += '.';
                    t += char('0' + rng.next() % 10);
                }
                break;
            }
            case 2: {  // from_chars' forms: exponents, '+', leading '.'
                const char* const forms[] = {"1e-3", "+2.5", ".75", "-.5", "3E2", "+0", "1.5e+1"};
                t = forms[rng.next() % 7];
                break;
            }
            default:
                t = std::to_string(rng.next() % 100000);
        }
        return t;
    };
    for (int file = 0; file < 200; ++file) {
        std::string text = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 8 8\nf 1 1 1 1 0 1 0 0\n";
        std::vector<std::string> tokens;
        std::vector<size_t> offsets;  // where each token starts in the text
        const int spheres = 1 + int(rng.next() % 50);
        for (int k = 0; k < 4 * spheres; ++k) {
            if (k % 4 == 0) text += std::string(separators[rng.next() % 8]) + "s";
            std::string t = randomToken();
            if (k % 4 == 3) {  // a radius: positive
                if (t[0] == '-' || t[0] == '+') t.erase(0, 1);
                if (!(reference(t).value_or(0) > 0)) t = "2.5";
            }
            tokens.push_back(t);
            text += separators[rng.next() % 8];
            offsets.push_back(text.size());
            text += t;
        }
        CAPTURE(text);
        const Scene scene = loadNffScene(text, "random.nff");
        REQUIRE(scene.objects.size() == size_t(spheres));
        for (int k = 0; k < spheres; ++k) {
            const auto* ball = dynamic_cast<const Sphere*>(scene.objects[size_t(k)].shape.get());
            REQUIRE(ball);
            const double got[4] = {ball->centre().x, ball->centre().y, ball->centre().z, ball->radius()};
            for (int c = 0; c < 4; ++c) {
                const std::optional<double> want = reference(tokens[size_t(4 * k + c)]);
                REQUIRE(want);
                CHECK(std::memcmp(&*want, &got[c], sizeof(double)) == 0);
            }
        }
        // One number short: the error names the line of the last number read.
        const size_t cut = offsets.back();
        std::string shortText = text.substr(0, cut);
        try {
            (void)loadNffScene(shortText, "short.nff");
            FAIL("a sphere of 3 numbers was accepted");
        } catch (const InputError& e) {
            CHECK(std::string(e.what()).find("got 3 numbers") != std::string::npos);
            // The third number's line, whatever the separator after it spans.
            int thirdLine = 1;
            for (size_t i = 0; i < offsets[offsets.size() - 2]; ++i) thirdLine += text[i] == '\n';
            CHECK(e.line() == thirdLine);
        }
    }
}

TEST_CASE("NFF numbers: tokens that are not plain decimals, read or refused as before") {
    // The one-pass path must leave these to from_chars and its errors: each
    // as the sphere's centre x, on line 9, followed by '#' with no space.
    const std::string head =
        "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 8 8\nf 1 1 1 1 0 1 0 0\n";
    for (const char* token : {"1.", "-", "1x", "1.5.2", "--1", "-.5", "+1", "1e3", "12345678901234567",
                              "0x10", "1-", "nan"}) {
        CAPTURE(token);
        const std::string text = head + "s " + token + "#c\n0 0 1\n";
        const std::optional<double> want = reference(token);
        if (want) {
            const Scene scene = loadNffScene(text, "token.nff");
            const auto* ball = dynamic_cast<const Sphere*>(scene.objects.at(0).shape.get());
            REQUIRE(ball);
            const double x = ball->centre().x;
            CHECK(std::memcmp(&*want, &x, sizeof x) == 0);
        } else {
            try {
                (void)loadNffScene(text, "token.nff");
                FAIL("accepted");
            } catch (const InputError& e) {
                CHECK(e.line() == 9);
                CHECK(std::string(e.what()).find(std::string("'") + token + "'") != std::string::npos);
            }
        }
    }
}

namespace {

/// nextToken restated one character at a time.
std::string_view tokenReference(std::string_view& rest) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    size_t a = 0;
    while (a < rest.size() && blank(rest[a])) ++a;
    size_t b = a;
    while (b < rest.size() && !blank(rest[b])) ++b;
    const std::string_view token = rest.substr(a, b - a);
    rest.remove_prefix(b);
    return token;
}

}  // namespace

TEST_CASE("nextToken: the tokens of the plain three-way blank test") {
    // isBlank is a bit test now: blanks, control characters inside tokens
    // ('\v', '\f', '\x01', '\0', '\n', '!' = 0x21), bytes from 0x80 (UTF-8).
    const char alphabet[] = {' ', '\t', '\r', 'a', '1', '-', '.', '\v', '\f', '\x01', '\0', '\n',
                             '!', '\x20', '\x21', '\x7f', '\x80', '\xc3', '\xa9', '\xff', '/'};
    Pcg32 rng(7, 3);
    for (int n = 0; n < 200000; ++n) {
        std::string text;
        const int len = int(rng.next() % 40);
        for (int k = 0; k < len; ++k) {
            // Runs of one kind so that long tokens and long blanks both occur.
            const char c = alphabet[rng.next() % sizeof alphabet];
            const int run = 1 + int(rng.next() % 9);
            for (int r = 0; r < run; ++r) text += c;
        }
        std::string_view a = text, b = text;
        for (int t = 0; t < 200; ++t) {
            const std::string_view got = nextToken(a), want = tokenReference(b);
            if (got.data() != want.data() || got.size() != want.size() || a.data() != b.data() ||
                a.size() != b.size()) {
                CAPTURE(text);
                FAIL_CHECK("nextToken differs from the reference");
                break;
            }
            if (got.empty()) break;
        }
    }
}
