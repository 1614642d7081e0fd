#include "renderer/image_compare.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "renderer/io/errors.h"

namespace raylab {

namespace {

std::string sizeText(const Film& f) {
    return std::to_string(f.width) + "x" + std::to_string(f.height);
}

void checkFilm(const Film& f, const char* which) {
    if (f.width < 0 || f.height < 0 || f.rgba.size() != size_t(f.width) * f.height * 4)
        throw InputError(std::string("image compare: image ") + which + " (" + sizeText(f) +
                         ") has " + std::to_string(f.rgba.size()) + " RGBA values");
}

}  // namespace

ImageComparison compareImages(const Film& a, const Film& b, double threshold) {
    checkFilm(a, "a");
    checkFilm(b, "b");
    if (a.width != b.width || a.height != b.height)
        throw InputError("image compare: sizes differ (" + sizeText(a) + " vs " + sizeText(b) +
                         ")");

    ImageComparison r;
    r.width = a.width;
    r.height = a.height;
    r.threshold = threshold;
    r.pixelCount = uint64_t(a.width) * uint64_t(a.height);

    double sumSq = 0;        // accumulated in pixel order: deterministic
    uint64_t compared = 0;   // finite R/G/B pairs in sumSq
    for (uint64_t i = 0; i < r.pixelCount; ++i) {
        const float* pa = &a.rgba[4 * i];
        const float* pb = &b.rgba[4 * i];
        if (std::memcmp(pa, pb, 4 * sizeof(float)) == 0) ++r.identicalPixels;
        for (int c = 0; c < 4; ++c) {
            r.nonFiniteA += !std::isfinite(pa[c]);
            r.nonFiniteB += !std::isfinite(pb[c]);
        }
        double pixelMax = 0;
        bool unbounded = false;
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(pa[c]) || !std::isfinite(pb[c])) {
                // Same bits (e.g. +inf in both) is agreement, anything else is
                // an error no threshold can accept.
                if (std::memcmp(&pa[c], &pb[c], sizeof(float)) != 0) unbounded = true;
                continue;
            }
            const double e = std::fabs(double(pa[c]) - double(pb[c]));
            sumSq += e * e;
            ++compared;
            if (e > pixelMax) pixelMax = e;
        }
        if (pixelMax > r.maxAbsError) r.maxAbsError = pixelMax;
        if (unbounded || pixelMax > threshold) ++r.pixelsOverThreshold;
    }
    r.rmse = compared ? std::sqrt(sumSq / double(compared)) : 0.0;
    r.psnr = r.rmse > 0 ? 20.0 * std::log10(1.0 / r.rmse)
                        : std::numeric_limits<double>::infinity();
    return r;
}

std::string formatPsnr(double psnr) {
    if (std::isinf(psnr)) return psnr > 0 ? "inf" : "-inf";
    if (std::isnan(psnr)) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", psnr);
    return buf;
}

}  // namespace raylab
