// raylab compare A.exr B.exr: how far apart two renders are (RMSE, PSNR,
// largest error, pixels visibly off, bit-identical pixels, NaN/Inf counts).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "apps/arg_parser.h"
#include "apps/commands.h"
#include "renderer/image_compare.h"
#include "renderer/io/errors.h"
#include "renderer/io/exr_reader.h"

namespace raylab {

namespace {
const char* const kCompareHelp =
    "usage: raylab compare A.exr B.exr [--threshold T]\n"
    "\n"
    "Compares the RGBA layers of two OpenEXR images of the same size: RMSE and PSNR (peak 1.0)\n"
    "over linear RGB, the largest channel error, pixels whose largest error exceeds T (default\n"
    "1e-3), pixels whose RGBA values are bit-identical, and NaN/Inf values. Exit code 0 when the\n"
    "images are bit-identical, 3 when they differ, 1 on unreadable input.\n";
}  // namespace

const CommandFlags kCompareFlags{"compare", kCompareHelp, {{"--threshold", "", true}}};

int compareCommand(const std::vector<std::string>& args) {
    std::vector<std::string> files;
    double threshold = 1e-3;
    ArgParser p(args, kCompareFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--threshold") {
            threshold = p.number(a, 0, 1e30);
        } else {
            files.push_back(a);
        }
    }
    if (files.size() != 2) throw UsageError("compare: expected two EXR files");
    const Film a = readExr(files[0]), b = readExr(files[1]);
    if (a.width != b.width || a.height != b.height)
        throw InputError(files[1], 0,
                         "size " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                             " differs from " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + " of " + files[0]);
    const ImageComparison c = compareImages(a, b, threshold);
    std::printf("pixels:            %llu (%dx%d)\n", (unsigned long long)c.pixelCount, c.width, c.height);
    std::printf("bit-identical:     %llu (%.4f%%)\n", (unsigned long long)c.identicalPixels,
                100.0 * double(c.identicalPixels) / double(c.pixelCount));
    std::printf("rmse:              %.6g\n", c.rmse);
    std::printf("psnr:              %s dB\n", formatPsnr(c.psnr).c_str());
    std::printf("max error:         %.6g\n", c.maxAbsError);
    std::printf("over %-12g  %llu pixels\n", c.threshold, (unsigned long long)c.pixelsOverThreshold);
    std::printf("non-finite:        %llu in A, %llu in B\n", (unsigned long long)c.nonFiniteA,
                (unsigned long long)c.nonFiniteB);
    return c.identicalPixels == c.pixelCount ? 0 : 3;
}

}  // namespace raylab
