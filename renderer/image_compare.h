#pragma once
// Pixel metrics between two renders of the same size (accuracy and
// accelerator-equivalence checks).

#include <cstdint>
#include <string>

#include "renderer/film.h"

namespace raylab {

struct ImageComparison {
    int width = 0, height = 0;
    /// Root mean square error over the R, G, B values of every pixel. Channel
    /// pairs where either value is non-finite are left out of rmse, psnr and
    /// maxAbsError (they are counted in nonFiniteA/B and pixelsOverThreshold).
    double rmse = 0;
    /// 20·log10(1 / rmse): peak signal 1.0; +inf when rmse is 0.
    double psnr = 0;
    double maxAbsError = 0;            ///< largest |a − b| over R, G, B
    double threshold = 0;              ///< the threshold pixelsOverThreshold used
    uint64_t pixelsOverThreshold = 0;  ///< pixels whose largest RGB error > threshold
    uint64_t nonFiniteA = 0;           ///< NaN/Inf values among the RGBA floats of a
    uint64_t nonFiniteB = 0;           ///< NaN/Inf values among the RGBA floats of b
    uint64_t identicalPixels = 0;      ///< pixels whose four RGBA floats are bit-identical
    uint64_t pixelCount = 0;           ///< width * height
};

/// \brief Compares the RGBA of two films of equal size.
///
/// A pixel counts towards pixelsOverThreshold when its largest R/G/B error
/// exceeds `threshold`, or when an R/G/B pair differs and either value is
/// non-finite (the error is then unbounded).
/// \throws InputError when the sizes differ or a film's rgba is inconsistent.
ImageComparison compareImages(const Film& a, const Film& b, double threshold = 1e-3);

/// \brief PSNR as text: "inf" for identical images, else "%.2f" dB digits.
std::string formatPsnr(double psnr);

}  // namespace raylab
