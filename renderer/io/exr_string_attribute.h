#pragma once
// An EXR string attribute that OpenEXR writes in one piece.
//
// Imf::StringAttribute writes its value one character at a time, and
// Header::writeTo sends each value through a std::ostringstream first (to
// learn its size): about 130 instructions per character. For the Cryptomatte
// manifest of balls.nff (7,400 objects, 185 kB) that was 25 M instructions on
// the main thread at every EXR write, whatever the resolution
// (docs/benchmarks.md, bar 3). This one writes the same bytes with one call:
// the type is "string", the value its characters with no terminator, so the
// file is byte for byte the same and any reader reads a StringAttribute.

#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <climits>
#include <string>

namespace raylab {

class ExrStringAttribute final : public Imf::StringAttribute {
public:
    explicit ExrStringAttribute(const std::string& value) : Imf::StringAttribute(value) {}

    Imf::Attribute* copy() const override { return new ExrStringAttribute(value()); }

    void writeValueTo(Imf::OStream& os, int /*version*/) const override {
        const std::string& s = value();
        for (size_t at = 0; at < s.size();) {  // OStream::write takes an int count
            const size_t n = std::min(s.size() - at, size_t(INT_MAX));
            os.write(s.data() + at, int(n));
            at += n;
        }
    }
};

}  // namespace raylab
