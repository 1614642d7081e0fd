#pragma once
// float -> half for the EXR's HALF channels, made safe first: NaN becomes 0
// and magnitudes beyond 65504 (the largest finite half) are clamped to it, so
// a HALF channel never holds Inf or NaN.
//
// Bit-identical to Imath's half(float) (round to nearest even; Imath itself
// compiles to the same F16C instruction when built with -mf16c): with F16C
// (every x86-64 CPU since 2012) eight values per instruction instead of ~35
// instructions per value, chosen at run time because the build targets
// baseline x86-64.

#include <cstddef>
#include <cstdint>

namespace raylab {

/// dst[i] = bits of half(clamp(src[i])), i < n.
void floatsToHalf(const float* src, uint16_t* dst, size_t n);

/// The portable path alone (for tests comparing it with floatsToHalf).
void floatsToHalfPortable(const float* src, uint16_t* dst, size_t n);

/// Whether floatsToHalf uses F16C on this CPU.
bool halfConversionUsesF16c();

}  // namespace raylab
