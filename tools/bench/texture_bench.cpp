#include "tools/bench/texture_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <unistd.h>
#include <vector>

#include "geometry/random.h"
#include "renderer/io/image_module_loader.h"
#include "renderer/io/image_reader.h"
#include "renderer/timing.h"
#include "shading/mipmap.h"
#include "tools/report/machine.h"

namespace raylab {

namespace {

struct Lookup {
    float s, t, dsdx, dtdx, dsdy, dtdy;
};

/// Random points, footprints of 0.5 to 16 texels, anisotropy up to 8, any angle.
std::vector<Lookup> makeLookups(int n, int size) {
    SplitMix64 rng(42);
    const auto uniform = [&] { return rng.uniform(); };
    std::vector<Lookup> v(static_cast<size_t>(n));
    for (Lookup& l : v) {
        l.s = float(uniform());
        l.t = float(uniform());
        const double major = std::exp2(-1 + 5 * uniform()) / size;
        const double minor = major / (1 + 7 * uniform());
        const double angle = 2 * M_PI * uniform();
        l.dsdx = float(major * std::cos(angle));
        l.dtdx = float(major * std::sin(angle));
        l.dsdy = float(-minor * std::sin(angle));
        l.dtdy = float(minor * std::cos(angle));
    }
    return v;
}

enum class Mode { Point, Bilinear, Trilinear, Anisotropic };
const char* modeName(Mode m) {
    switch (m) {
    case Mode::Point: return "point";
    case Mode::Bilinear: return "bilinear";
    case Mode::Trilinear: return "trilinear";
    case Mode::Anisotropic: return "anisotropic";
    }
    return "?";
}

Texel ownLookup(const MipMap& m, Mode mode, const Lookup& l) {
    const Vec2 st{l.s, l.t}, dx{l.dsdx, l.dtdx}, dy{l.dsdy, l.dtdy};
    switch (mode) {
    case Mode::Point: return m.point(st, WrapMode::Repeat);
    case Mode::Bilinear: return m.bilinear(0, st, WrapMode::Repeat);
    case Mode::Trilinear: return m.trilinear(st, dx, dy, WrapMode::Repeat);
    case Mode::Anisotropic: break;
    }
    return m.ewa(st, dx, dy, WrapMode::Repeat);
}

image_module::Filter moduleFilter(Mode mode) {
    switch (mode) {
    case Mode::Point: return image_module::Filter::Point;
    case Mode::Bilinear: return image_module::Filter::Bilinear;
    case Mode::Trilinear: return image_module::Filter::Trilinear;
    case Mode::Anisotropic: break;
    }
    return image_module::Filter::Anisotropic;
}

}  // namespace

void runTextureBench(const TextureBenchOptions& o, std::ostream& out) {
    const int n = o.size;
    // A linear float image (so both sides filter the same values): smooth
    // gradients plus a one-texel checker, the hardest case for a filter.
    std::vector<float> texels(size_t(n) * n * 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            float* p = &texels[(size_t(y) * n + x) * 3];
            p[0] = float(x) / n;
            p[1] = float(y) / n;
            p[2] = float((x + y) % 2);
        }
    const std::string path =
        (std::filesystem::temp_directory_path() / ("raylab_texbench_" + std::to_string(::getpid()) + ".exr")).string();
    // OpenImageIO's side runs in raylab's image module (image_module.h).
    const image_module::Api& oiio = imageModule(path);
    std::string error;
    if (!oiio.writeFloat(path, n, n, 3, texels.data(), error))
        throw std::runtime_error("bench textures: cannot write " + path + ": " + error);
    struct Remove {
        std::string p;
        ~Remove() { std::filesystem::remove(p); }
    } remove{path};

    // Own pyramid: read and built as a render does.
    double t0 = threadCpuSeconds();
    ImageData image = readImage(path, ImageRole::Color, std::nullopt);
    const MipMap mip(image.width, image.height, image.channels, std::move(image.texels));
    const double ownLoad = threadCpuSeconds() - t0;

    const std::unique_ptr<image_module::TextureSystemFile> ts = oiio.openTextureSystem(path, error);
    if (!ts) throw std::runtime_error("bench textures: OpenImageIO's TextureSystem: " + error);

    const std::vector<Lookup> lookups = makeLookups(o.lookups, n);
    // The first OIIO lookup reads the file and builds its MIP levels.
    t0 = threadCpuSeconds();
    float warm[3];
    ts->lookup(image_module::Filter::Trilinear, 0.5f, 0.5f, 0, 0, 0, 0, 3, warm);
    const double oiioLoad = threadCpuSeconds() - t0;

    out << "Texture lookups: " << n << "x" << n << " RGB float image, " << o.lookups
        << " lookups per run, fastest of " << o.runs << " runs, one thread (CPU time)\n";
    out << "machine: " << cpuModelName() << "\n";
    char line[256];
    std::snprintf(line, sizeof line, "load and MIP build: raylab %.1f ms, OpenImageIO %.1f ms\n\n",
                  ownLoad * 1e3, oiioLoad * 1e3);
    out << line;
    out << "| filter | raylab ns/lookup | OpenImageIO ns/lookup | OIIO / raylab | mean |diff| |\n";
    out << "|---|---:|---:|---:|---:|\n";
    for (Mode mode : {Mode::Point, Mode::Bilinear, Mode::Trilinear, Mode::Anisotropic}) {
        double bestOwn = 1e30, bestOiio = 1e30, sink = 0;
        const image_module::Filter filter = moduleFilter(mode);
        for (int run = 0; run < o.runs; ++run) {
            t0 = threadCpuSeconds();
            for (const Lookup& l : lookups) sink += ownLookup(mip, mode, l)[0];
            bestOwn = std::min(bestOwn, threadCpuSeconds() - t0);
            t0 = threadCpuSeconds();
            for (const Lookup& l : lookups) {
                float r[3];
                ts->lookup(filter, l.s, l.t, l.dsdx, l.dtdx, l.dsdy, l.dtdy, 3, r);
                sink += r[0];
            }
            bestOiio = std::min(bestOiio, threadCpuSeconds() - t0);
        }
        double diff = 0;
        for (const Lookup& l : lookups) {
            float r[3];
            ts->lookup(filter, l.s, l.t, l.dsdx, l.dtdx, l.dsdy, l.dtdy, 3, r);
            const Texel own = ownLookup(mip, mode, l);
            for (int c = 0; c < 3; ++c) diff += std::abs(own[size_t(c)] - r[c]);
        }
        diff /= 3.0 * lookups.size();
        const double ownNs = bestOwn / lookups.size() * 1e9, oiioNs = bestOiio / lookups.size() * 1e9;
        std::snprintf(line, sizeof line, "| %s | %.1f | %.1f | %.1fx | %.4f |%s\n", modeName(mode),
                      ownNs, oiioNs, oiioNs / ownNs, diff, sink == 12345.678 ? " " : "");
        out << line;
    }
}

}  // namespace raylab
