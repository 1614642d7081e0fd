#include "renderer/io/half_convert.h"

#include <cpuid.h>

#include <immintrin.h>

#include <cmath>

#include <Imath/half.h>

#include "renderer/io/finite_clamp.h"

namespace raylab {

namespace {

constexpr float kHalfMax = 65504.0f;  // largest finite half

/// NaN -> 0, |v| > 65504 -> ±65504. Clamped before rounding because Imath
/// rounds to nearest: anything from 65520 up would become Inf.
float safeForHalf(float v) { return finiteClamp(v, kHalfMax); }

__attribute__((target("avx,f16c"))) void floatsToHalfF16c(const float* src, uint16_t* dst,
                                                           size_t n) {
    const __m256 hi = _mm256_set1_ps(kHalfMax), lo = _mm256_set1_ps(-kHalfMax);
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        __m256 v = _mm256_loadu_ps(src + i);
        // NaN lanes -> +0 (andnot of the unordered mask), then the clamp;
        // min/max return their second operand for NaN, which is gone by now.
        v = _mm256_andnot_ps(_mm256_cmp_ps(v, v, _CMP_UNORD_Q), v);
        v = _mm256_max_ps(_mm256_min_ps(v, hi), lo);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + i),
                         _mm256_cvtps_ph(v, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC));
    }
    for (; i < n; ++i) {
        const __m128 v = _mm_set_ss(safeForHalf(src[i]));
        dst[i] = uint16_t(_mm_extract_epi16(
            _mm_cvtps_ph(v, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC), 0));
    }
}

bool cpuHasF16c() {
    // cpuid directly: clang 14's __builtin_cpu_supports does not know "f16c".
    // VEX instructions also need the OS to save the AVX state (OSXSAVE, XCR0).
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (!__get_cpuid(1, &eax, &ebx, &ecx, &edx)) return false;
    const bool osxsave = (ecx & (1u << 27)) != 0, avx = (ecx & (1u << 28)) != 0,
               f16c = (ecx & (1u << 29)) != 0;
    if (!osxsave || !avx || !f16c) return false;
    unsigned xcr0Low = 0, xcr0High = 0;
    __asm__ volatile("xgetbv" : "=a"(xcr0Low), "=d"(xcr0High) : "c"(0));
    return (xcr0Low & 6u) == 6u;  // SSE and AVX state enabled
}

}  // namespace

void floatsToHalfPortable(const float* src, uint16_t* dst, size_t n) {
    for (size_t i = 0; i < n; ++i) dst[i] = Imath::half(safeForHalf(src[i])).bits();
}

bool halfConversionUsesF16c() {
    static const bool has = cpuHasF16c();
    return has;
}

void floatsToHalf(const float* src, uint16_t* dst, size_t n) {
    if (halfConversionUsesF16c())
        floatsToHalfF16c(src, dst, n);
    else
        floatsToHalfPortable(src, dst, n);
}

}  // namespace raylab
