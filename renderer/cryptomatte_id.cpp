#include "renderer/cryptomatte_id.h"

#include <cstring>
#include <string_view>
#include <vector>

#include "renderer/io/json_string.h"

namespace raylab {

namespace {

uint32_t rotl32(uint32_t x, int r) { return (x << r) | (x >> (32 - r)); }

/// MurmurHash3's finalisation mix: every input bit affects every output bit.
uint32_t fmix32(uint32_t h) {
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

}  // namespace

uint32_t murmurHash3_x86_32(const void* data, size_t len, uint32_t seed) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    const uint32_t c1 = 0xcc9e2d51u, c2 = 0x1b873593u;
    uint32_t h = seed;
    const size_t blocks = len / 4;
    for (size_t i = 0; i < blocks; ++i) {
        // Blocks are read little-endian, as on the x86 the reference targets.
        const unsigned char* p = bytes + 4 * i;
        uint32_t k = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 |
                     uint32_t(p[3]) << 24;
        k *= c1;
        k = rotl32(k, 15);
        k *= c2;
        h ^= k;
        h = rotl32(h, 13);
        h = h * 5 + 0xe6546b64u;
    }
    const unsigned char* tail = bytes + 4 * blocks;
    uint32_t k = 0;
    switch (len & 3) {
        case 3: k ^= uint32_t(tail[2]) << 16; [[fallthrough]];
        case 2: k ^= uint32_t(tail[1]) << 8; [[fallthrough]];
        case 1:
            k ^= tail[0];
            k *= c1;
            k = rotl32(k, 15);
            k *= c2;
            h ^= k;
    }
    h ^= uint32_t(len);
    return fmix32(h);
}

uint32_t cryptomatteIdBits(const std::string& name) {
    uint32_t bits = murmurHash3_x86_32(name.data(), name.size(), 0);
    const uint32_t exponent = (bits >> 23) & 255u;
    if (exponent == 0 || exponent == 255) bits ^= 1u << 23;
    return bits;
}

float cryptomatteIdFloat(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

namespace {

/// The 8 lower-case hex digits of `bits`, most significant first, at `out`.
void writeHex8(char* out, uint32_t bits) {
    static const char digits[] = "0123456789abcdef";
    for (int i = 7; i >= 0; --i, bits >>= 4) out[i] = digits[bits & 15u];
}

}  // namespace

std::string cryptomatteHex(uint32_t bits) {
    std::string s(8, '0');
    writeHex8(s.data(), bits);
    return s;
}

std::string cryptomatteLayerKey(const std::string& layerName) {
    return cryptomatteHex(cryptomatteIdBits(layerName)).substr(0, 7);
}

std::string cryptomatteManifest(const std::vector<std::string>& names) {
    // Thousands of names per frame (one per SPD primitive): sized once and
    // appended in place, no string made per name. The names seen are found in
    // an open-addressing table keyed by the name's id, which the manifest
    // computes anyway: a std::unordered_set allocated a node and hashed every
    // name a second time (balls.nff's manifest: 8.6 -> 3.7 M instructions).
    size_t bytes = 2;
    for (const std::string& name : names) bytes += name.size() + 14;  // "name":"8hex",
    std::string json;
    json.reserve(bytes);
    json += '{';
    // At most half full, so every probe ends at an empty slot. Names are
    // compared, not ids: two names may share an id, and both are listed.
    size_t slots = 16;
    while (slots < 2 * names.size()) slots *= 2;
    std::vector<const std::string*> seen(slots, nullptr);
    for (const std::string& name : names) {
        const uint32_t bits = cryptomatteIdBits(name);
        size_t slot = size_t(bits) & (slots - 1);
        bool repeated = false;
        for (; seen[slot]; slot = (slot + 1) & (slots - 1))
            if (*seen[slot] == name) {
                repeated = true;
                break;
            }
        if (repeated) continue;
        seen[slot] = &name;
        if (json.size() > 1) json += ',';
        appendJsonString(json, name);
        char value[11] = {':', '"', 0, 0, 0, 0, 0, 0, 0, 0, '"'};  // :"8hex"
        writeHex8(value + 2, bits);
        json.append(value, sizeof value);
    }
    json += '}';
    return json;
}

}  // namespace raylab
