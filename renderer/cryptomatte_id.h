#pragma once
// Cryptomatte ids (Psyop's Cryptomatte specification, v1.2): an object's name
// hashed with MurmurHash3_x86_32 (seed 0), stored in a FLOAT channel as the
// bits of that 32-bit hash. Hashes whose float exponent would be 0 (denormal)
// or 255 (Inf/NaN) get exponent bit 23 flipped, as the specification's
// reference code does, so every id is a normal finite float.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/// MurmurHash3_x86_32 (Austin Appleby's public-domain hash) of `len` bytes.
uint32_t murmurHash3_x86_32(const void* data, size_t len, uint32_t seed = 0);

/// The id bits of `name`: its hash with the exponent fix above.
uint32_t cryptomatteIdBits(const std::string& name);

/// The float whose bits are `bits` (what the CryptoObject channels hold).
float cryptomatteIdFloat(uint32_t bits);

/// `bits` as 8 lower-case hex digits (the manifest's spelling).
std::string cryptomatteHex(uint32_t bits);

/// The 7-hex-digit key of a Cryptomatte layer's header attributes,
/// cryptomatte/<key>/...: the first 7 digits of the layer name's id.
std::string cryptomatteLayerKey(const std::string& layerName);

/// The manifest: a JSON object from each distinct name to its id in hex,
/// in the order of first appearance.
std::string cryptomatteManifest(const std::vector<std::string>& names);

}  // namespace raylab
