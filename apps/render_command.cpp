// raylab render: load → build → render → write.

#include <sys/stat.h>
#include <unistd.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <system_error>
#include <utility>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "apps/arg_parser.h"
#include "apps/commands.h"
#include "apps/exit_keep.h"
#include "apps/heap_pages.h"
#include "apps/progress_bar.h"
#include "apps/run_phase.h"
#include "apps/signals.h"
#include "distributed/frame_sequence.h"
#include "distributed/mpi_render.h"
#include "distributed/rank_agreement.h"
#include "renderer/accel/accelerator.h"
#include "renderer/camera_matrices.h"
#include "renderer/cancel.h"
#include "renderer/crop_window.h"
#include "renderer/effects.h"
#include "renderer/first_look.h"
#include "renderer/huge_page_allocator.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/exr_writer.h"
#include "renderer/io/file_identity.h"
#include "renderer/io/input_files.h"
#include "renderer/io/loading_file.h"
#include "renderer/io/oiio_writer.h"
#include "renderer/io/output_format.h"
#include "renderer/io/output_names.h"
#include "renderer/io/png_writer.h"
#include "renderer/io/scene_loader.h"
#include "renderer/io/text_file.h"
#include "renderer/matte_coverage.h"
#include "renderer/memory_limit.h"
#include "renderer/polygon_options.h"
#include "renderer/render.h"
#include "renderer/render_option_names.h"
#include "renderer/render_settings_text.h"
#include "renderer/render_setup.h"
#include "renderer/version.h"
#include "renderer/timing.h"

namespace raylab {

const char* const kRenderHelp =
    "usage: raylab render SCENE -o OUT.exr [-o OUT.png ...] [options]\n"
    "\n"
    "Renders SCENE (.json native format, .obj mesh alone, .nff Haines' NFF) to images. The EXR has\n"
    "RGBA plus Z (planar depth), distance, N (normal), albedo, objectId and Cryptomatte object\n"
    "mattes (docs/output.md). Flags override the scene's settings.\n"
    "\n"
    "output:\n"
    "  -o, --output FILE        an output image, its format by extension (at least one; repeat\n"
    "                           for several): .exr (every layer), .png and .jpg/.jpeg (8-bit sRGB,\n"
    "                           tone-mapped with --exposure), .hdr (Radiance, linear RGB),\n"
    "                           .tif/.tiff (32-bit float linear RGBA); the layers are computed\n"
    "                           only when an output is an EXR. JPEG, HDR and TIFF through\n"
    "                           OpenImageIO, loaded (before the render) only for them. Every\n"
    "                           output path is checked before the render (one that is a file the\n"
    "                           render reads, or another output, is refused); the files are\n"
    "                           written to temporary names and renamed only once all are written,\n"
    "                           and put back if a rename fails, so a failed write leaves existing\n"
    "                           files as they were (their mode is kept). A symbolic link is\n"
    "                           followed (its target is replaced); a device, FIFO or socket is\n"
    "                           refused\n"
    "  --png FILE.png           the same as -o FILE.png (a tone-mapped sRGB preview)\n"
    "  --exposure E             exposure in stops of the 8-bit outputs (default 0)\n"
    "  --float                  32-bit float RGBA in the EXR (default: half)\n"
    "  --alpha background|transparent|opaque   where camera rays miss: background (default)\n"
    "                           keeps the background colour in RGB with A = object coverage;\n"
    "                           transparent leaves it out (RGB premultiplied by A, for an \"over\");\n"
    "                           opaque keeps it with A = 1\n"
    "  --compression none|rle|zips|zip|piz   lossless EXR compression (default zip, by ISA-L's\n"
    "                           igzip; none and rle write fastest, zip and piz smallest:\n"
    "                           docs/benchmarks.md). none, rle and piz are written by\n"
    "                           OpenEXR, loaded for them (raylab-openexr.so)\n"
    "  --fsync                  also make the outputs survive a power loss: each file is flushed\n"
    "                           to the disk (fsync) before its rename and its folder after\n"
    "                           (costs ~0.1 s per fsync on a busy disk). Without it the outputs\n"
    "                           are still replaced atomically for a crash, a signal or a reader\n"
    "                           (docs/robustness.md#output-commit)\n"
    "  --stats FILE             write statistics as JSON (rays per type and depth, times, effects,\n"
    "                           samples that reached the ray cap, the objects with their objectId\n"
    "                           and Cryptomatte id)\n"
    "  --frames A:B             render frames A..B of the scene's camera_path: OUT_0001.exr ...\n"
    "                           (and every other output numbered alike)\n"
    "  -q, --quiet              no progress bar and no summary (the bar is drawn only when\n"
    "                           stderr is a terminal)\n"
    "\n"
    "image:\n"
    "  --width W, --height H    resolution in pixels (1..65536)\n"
    "  --spp N                  samples per pixel (1..65536), stratified and jittered when N > 1\n"
    "                           (default 1); not with --adaptive or --spd, which sample pixel\n"
    "                           corners instead (a scene file's spp is then ignored)\n"
    "  --depth D                ray-tree depth limit (1..64), the camera ray is depth 1 (default 5)\n"
    "  --seed S                 seed of the per-pixel jitter (0..2^53, default 0)\n"
    "  --adaptive T             Whitted adaptive supersampling: subdivide where corner samples differ\n"
    "                           by more than T (0 = off)\n"
    "  --adaptive-levels L      maximum subdivision levels for --adaptive (1..8, default 2)\n"
    "  --min-weight W           prune rays whose accumulated weight is below W (default 0 = off)\n"
    "  --max-rays N             rays (every type) one camera sample may trace before its reflection\n"
    "                           and refraction rays stop (1..2^40, default 65536): bounds the work\n"
    "                           of a pixel; samples that reach it are counted and warned about\n"
    "  --spd                    Haines' SPD testing procedure: 512x512, rays through pixel corners,\n"
    "                           depth 5, zero-weight reflection rays traced and counted\n"
    "  --crop X0,X1,Y0,Y1       render only the window [X0,X1) x [Y0,Y1) of the image, in NDC\n"
    "                           (0..1 of the width and height, y from the top; pbrt's\n"
    "                           --cropwindow): pixels ceil(X0*W) .. ceil(X1*W)-1, likewise in y.\n"
    "                           The EXR keeps the full image as its display window and the crop\n"
    "                           as its data window; the PNG is the crop. Each pixel is bit-identical\n"
    "                           to the same pixel of the full render (--spp, --adaptive, --spd\n"
    "                           and mpirun included)\n"
    "\n"
    "camera (any scene type; each flag replaces the scene's value, the others are kept):\n"
    "  --eye X,Y,Z              eye position\n"
    "  --look-at X,Y,Z          the point at the image centre\n"
    "  --camera-up X,Y,Z        up vector (need not be perpendicular to the view)\n"
    "  --fov DEG                full vertical field of view in degrees, in (0, 180) (perspective)\n"
    "\n"
    "bare .obj scenes (framed by raylab: the silhouette fills about 80% of the image):\n"
    "  --up x|y|z|-x|-y|-z      the model's up axis (default y; z for CAD models and terrains)\n"
    "  --normals file|flat|smooth   shading normals. file (default): the file's vn, else\n"
    "                           averaged within each smoothing group 's'; flat: every face flat,\n"
    "                           even with vn; smooth: the file's vn, else averaged over the mesh\n"
    "\n"
    "performance and accuracy:\n"
    "  --threads N              threads of the whole command: loading, build, render and output\n"
    "                           (default: all cores); the image does not depend on it\n"
    "  --accel embree|naive     Embree BVH (default) or the textbook loop over all objects\n"
    "  --bvh-quality low|medium|high   Embree build quality (default medium)\n"
    "  --robust, --no-robust    Embree's robust traversal, watertight on triangle edges (default),\n"
    "                           or its fast one, which lets 5-15% of rays aimed exactly at an edge\n"
    "                           through (JSON render.robust)\n"
    "  --precision float|double arithmetic of the analytic intersectors (default double)\n"
    "  --shadows opaque|filtered  shadow feelers through transmitters: filtered (default) dims the\n"
    "                           light by the kt of every transmitter crossed (no refraction of the\n"
    "                           feeler); opaque blocks it, the classic Whitted shadow (and --spd's)\n"
    "  --alpha-cutoff C         the cut-off of every material's alpha, in [0, 1]: a hit whose\n"
    "                           alpha (x its mask) is below C is a hole (default: each\n"
    "                           material's alpha_cutoff, 0.5 unless set)\n"
    "  --epsilon E              lecture-style self-intersection avoidance: secondary rays accept\n"
    "                           t > E (default: robust offset along the normal, scaled to |p|)\n"
    "  --polygons watertight|projected|triangles   planar polygons: the watertight ray-space\n"
    "                           inside test (default), the lecture's projected 2D test, or ear-\n"
    "                           clipped into Embree triangles (two-sided)\n"
    "  --effects auto|all       auto (default): the kernel specialised to the effects the scene\n"
    "                           uses; all: the general kernel, every ray type at every hit with\n"
    "                           pruning off (the same picture, slower: docs/effects.md)\n"
    "\n"
    "textures (docs/accuracy.md#textures):\n"
    "  --texture-filter point|bilinear|trilinear|anisotropic   lookups: nearest texel or bilinear\n"
    "                           on the full image, or filtered over each sample's footprint:\n"
    "                           trilinear MIP mapping or EWA (default trilinear)\n"
    "  --texture-footprint cones|differentials   how footprints travel with rays: ray cones or\n"
    "                           Igehy's ray differentials (default differentials)\n"
    "\n"
    "distributed (docs/distributed.md):\n"
    "  mpirun -np N raylab render SCENE -o OUT.exr ...   N processes render one image (or\n"
    "                           sequence), bit-identical to one process; rank 0 writes the files;\n"
    "                           --threads defaults to the cores of a machine / its ranks; every\n"
    "                           rank must read the same scene bytes and image flags (checked)\n"
    "\n"
    "Flags take their value as '--flag value' or '--flag=value'.\n"
    "SIGINT, SIGTERM and SIGHUP stop the render in any phase: temporaries are removed, earlier\n"
    "outputs are left as they were, exit code 128+signal (130, 143, 129).\n";

const CommandFlags kRenderFlags{
    "render",
    kRenderHelp,
    {{"--output", "-o", true},      {"--png", "", true},         {"--exposure", "", true},
     {"--float", "", false},        {"--alpha", "", true},       {"--compression", "", true},
     {"--fsync", "", false},        {"--stats", "", true},
     {"--frames", "", true},
     {"--quiet", "-q", false},      {"--width", "", true},       {"--height", "", true},
     {"--spp", "", true},           {"--depth", "", true},       {"--seed", "", true},
     {"--max-rays", "", true},
     {"--adaptive", "", true},      {"--adaptive-levels", "", true}, {"--min-weight", "", true},
     {"--spd", "", false},          {"--crop", "", true},        {"--eye", "", true},
     {"--look-at", "", true},       {"--camera-up", "", true},   {"--fov", "", true},
     {"--up", "", true},            {"--normals", "", true},     {"--threads", "", true},
     {"--accel", "", true},         {"--bvh-quality", "", true}, {"--robust", "", false},
     {"--no-robust", "", false},
     {"--precision", "", true},     {"--shadows", "", true},     {"--alpha-cutoff", "", true},
     {"--epsilon", "", true},
     {"--polygons", "", true},      {"--effects", "", true},     {"--texture-filter", "", true},
     {"--texture-footprint", "", true}}};

namespace {

struct RenderCli {
    std::string scene, stats;
    std::vector<OutputFlag> images;    ///< -o and --png, in the order given
    std::optional<FrameRange> frames;  ///< --frames: a camera_path sequence
    bool triangulatePolygons = false;  ///< --polygons triangles
    bool quiet = false, floatPixels = false;
    bool fsync = false;  ///< --fsync: outputs durable across a power loss
    ExrCompression compression = ExrCompression::Zip;
    double exposure = 0;
    RenderOverrides overrides;
    CameraOverrides camera;    ///< --eye, --look-at, --camera-up, --fov
    std::optional<Vec3> upAxis;  ///< --up (bare .obj)
    std::optional<ObjNormals> normals;  ///< --normals (bare .obj)
    std::optional<CropWindow> crop;     ///< --crop, in NDC
};

Vec3 toVec3(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

/// --crop X0,X1,Y0,Y1: four numbers in [0, 1], X0 < X1 and Y0 < Y1 (pbrt's order).
CropWindow parseCropWindow(const std::string& flag, const std::string& v) {
    const std::string expected = flag + ": expected X0,X1,Y0,Y1 in [0, 1] with X0 < X1 and Y0 < Y1 (got '" + v + "')";
    double c[4];
    size_t start = 0;
    for (int i = 0; i < 4; ++i) {
        const size_t comma = v.find(',', start);
        if ((i < 3) != (comma != std::string::npos)) throw UsageError(expected);
        const std::string part = v.substr(start, i < 3 ? comma - start : std::string::npos);
        char* end = nullptr;
        c[i] = std::strtod(part.c_str(), &end);
        if (part.empty() || std::isspace(static_cast<unsigned char>(part[0])) || *end != '\0' ||
            !(c[i] >= 0 && c[i] <= 1))
            throw UsageError(expected);
        start = comma + 1;
    }
    if (!(c[0] < c[1] && c[2] < c[3])) throw UsageError(expected);
    return {c[0], c[1], c[2], c[3]};
}

/// The output flags of a render, for checkOutputNames.
std::vector<OutputFlag> outputFlags(const RenderCli& cli) {
    std::vector<OutputFlag> flags = cli.images;
    flags.push_back({"--stats", cli.stats});
    return flags;
}

/// Refuses outputs that name one another or a file the render reads (all of
/// them once loaded; the scene alone before, so that mistake costs no load).
void checkOutputs(const RenderCli& cli, const std::vector<InputFile>& inputs) {
    const OutputFrames numbering{cli.frames ? cli.frames->first : 1,
                                 cli.frames ? cli.frames->last : 1, sequenceFileName};
    checkOutputNames(outputFlags(cli), cli.frames ? &numbering : nullptr, inputs);
}

/// loadScene, with an out-of-memory failure reported at the file being read.
Scene loadSceneNamingFile(const std::string& path, const SceneLoadOptions& options) {
    try {
        return loadScene(path, options);
    } catch (const std::bad_alloc&) {
        const std::string file = fileBeingLoaded().empty() ? path : fileBeingLoaded();
        // The limit as set (what is left of it is about nothing by now).
        const MemoryFacts facts = readMemoryFacts();
        const auto mib = [](double b) { return std::to_string((long long)(b / (1 << 20))) + " MiB"; };
        std::string limit;
        if (facts.addressSpaceBytes) limit = " (ulimit -v: " + mib(*facts.addressSpaceBytes) + ")";
        else if (facts.cgroupLimitBytes) limit = " (cgroup memory limit: " + mib(*facts.cgroupLimitBytes) + ")";
        throw InputError(file, 0, "out of memory while loading this file" + limit);
    }
}

RenderCli parseRenderArgs(const std::vector<std::string>& args) {
    RenderCli cli;
    ArgParser p(args, kRenderFlags);
    RenderOverrides& o = cli.overrides;
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "-o" || a == "--output") cli.images.push_back({"-o", p.repeatableValue(a)});
        else if (a == "--png") cli.images.push_back({"--png", p.repeatableValue(a)});
        else if (a == "--alpha") o.alpha = p.choice(a, alphaModeNames());
        else if (a == "--stats") cli.stats = p.value(a);
        else if (a == "--frames") cli.frames = parseFrameRange(p.value(a));
        else if (a == "--polygons") {
            const std::string v = p.choice(a, {"watertight", "projected", "triangles"});
            if (v == "triangles") cli.triangulatePolygons = true;
            else o.polygonTest = v == "projected" ? PolygonTest::Projected : PolygonTest::Watertight;
        }
        else if (a == "--quiet" || a == "-q") cli.quiet = true;
        else if (a == "--float") cli.floatPixels = true;
        else if (a == "--fsync") cli.fsync = true;
        else if (a == "--compression") {
            const std::string v = p.choice(a, {std::begin(kExrCompressionNames),
                                               std::end(kExrCompressionNames)});
            for (size_t i = 0; i < std::size(kExrCompressionNames); ++i)
                if (v == kExrCompressionNames[i]) cli.compression = ExrCompression(i);
        }
        else if (a == "--exposure") cli.exposure = p.number(a, -64, 64);
        else if (a == "--width") o.width = int(p.integer(a, 1, kMaxImageSide));
        else if (a == "--height") o.height = int(p.integer(a, 1, kMaxImageSide));
        else if (a == "--spp") o.spp = int(p.integer(a, 1, kMaxSpp));
        else if (a == "--depth") o.maxDepth = int(p.integer(a, 1, kMaxDepth));
        else if (a == "--seed") o.seed = uint64_t(p.integer(a, 0, kMaxSeed));
        else if (a == "--max-rays") o.maxRaysPerSample = uint64_t(p.integer(a, 1, kMaxRaysPerSampleLimit));
        else if (a == "--adaptive") o.adaptiveThreshold = p.number(a, 0, 1e30);
        else if (a == "--adaptive-levels") o.adaptiveMaxLevel = int(p.integer(a, 1, kMaxAdaptiveLevels));
        else if (a == "--min-weight") o.minWeight = p.number(a, 0, 1);
        else if (a == "--spd") o.spd = true;
        else if (a == "--threads") o.threads = int(p.integer(a, 1, 4096));
        else if (a == "--accel") o.accel = p.choice(a, acceleratorNames());
        else if (a == "--bvh-quality") o.bvhQuality = p.choice(a, bvhQualityNames());
        else if (a == "--robust") o.robust = true;
        else if (a == "--no-robust") o.robust = false;
        else if (a == "--shadows") o.shadows = p.choice(a, shadowModeNames());
        else if (a == "--alpha-cutoff") o.alphaCutoff = p.number(a, 0, 1);
        else if (a == "--precision") o.precision = p.choice(a, precisionNames());
        else if (a == "--epsilon") o.epsilon = p.number(a, 0, 1e30);
        else if (a == "--eye") cli.camera.eye = toVec3(p.triple(a));
        else if (a == "--look-at") cli.camera.lookAt = toVec3(p.triple(a));
        else if (a == "--camera-up") cli.camera.up = toVec3(p.triple(a));
        else if (a == "--fov") {
            cli.camera.vfovDegrees = p.number(a, 0, 180);
            if (!(*cli.camera.vfovDegrees > 0 && *cli.camera.vfovDegrees < 180))
                throw UsageError("--fov: expected degrees in (0, 180) (got " +
                                 std::to_string(*cli.camera.vfovDegrees) + ")");
        }
        else if (a == "--normals") {
            const std::string v = p.choice(a, {"file", "flat", "smooth"});
            cli.normals = v == "flat" ? ObjNormals::Flat
                                      : v == "smooth" ? ObjNormals::Smooth : ObjNormals::File;
        }
        else if (a == "--up")
            cli.upAxis = upAxisNamed(p.choice(a, {"x", "y", "z", "-x", "-y", "-z"}));
        else if (a == "--texture-filter") o.textureFilter = p.choice(a, textureFilterNames());
        else if (a == "--texture-footprint")
            o.textureFootprint = p.choice(a, textureFootprintNames());
        else if (a == "--effects") o.effects = p.choice(a, effectsModeNames());
        else if (a == "--crop") cli.crop = parseCropWindow(a, p.value(a));
        else if (!a.empty() && a[0] == '-') throw std::logic_error("render: flag '" + a + "' declared but not handled");
        else if (cli.scene.empty()) cli.scene = a;
        else throw UsageError("unexpected argument '" + a + "' (one scene per render)");
    }
    if (cli.scene.empty()) throw UsageError("render: missing SCENE (see 'raylab render --help')");
    if (cli.images.empty())
        throw UsageError(std::string("render: missing -o OUT (") + outputExtensionList() + ")");
    if (cli.upAxis && lowerExtension(cli.scene) != ".obj")
        throw UsageError("--up: only a bare .obj scene is framed by raylab (got '" + cli.scene +
                         "'); set the camera with --eye, --look-at and --camera-up");
    if (cli.normals && lowerExtension(cli.scene) != ".obj")
        throw UsageError("--normals: only for a bare .obj scene (a JSON mesh has the \"normals\" "
                         "key)");
    if (cli.frames && cli.camera.any())
        throw UsageError("--eye, --look-at, --camera-up and --fov cannot be combined with "
                         "--frames: the scene's camera_path sets every frame's camera");
    // Two names for one file would make one output overwrite another, or the scene.
    std::vector<InputFile> scene;
    struct stat st {};
    if (::stat(cli.scene.c_str(), &st) == 0) scene.push_back({cli.scene, fileKeyOf(st)});
    checkOutputs(cli, scene);
    // The format is the extension's: a name without a known one is a typing
    // mistake that would only show up when another program opens the file.
    for (const OutputFlag& image : cli.images) {
        const std::optional<OutputFormat> format = outputFormatOf(image.path);
        if (image.flag == "--png" && format != OutputFormat::Png)
            throw UsageError("--png: the name must end in .png (got '" + image.path + "')");
        if (!format)
            throw UsageError(image.flag + ": the format is chosen by the extension, one of " +
                             outputExtensionList() + " (got '" + image.path + "')");
    }
    return cli;
}

/// A bare .obj is framed for the image it will be rendered into: the up
/// axis and the aspect of --width/--height (its own defaults otherwise).
SceneLoadOptions sceneLoadOptions(const RenderCli& cli) {
    SceneLoadOptions o;
    if (cli.upAxis) o.up = *cli.upAxis;
    if (cli.normals) o.normals = *cli.normals;
    const ImageSettings defaults;
    o.aspect = cli.overrides.spd ? 1.0  // SPD images are square
                                 : double(cli.overrides.width.value_or(defaults.width)) /
                                       double(cli.overrides.height.value_or(defaults.height));
    return o;
}

/// The one warning of a run whose samples reached the ray cap (`frame` 0:
/// not a sequence).
std::string rayCapWarning(const RenderResult& r, const RenderOptions& o, int frame) {
    const uint64_t samples = r.rays.total(RayType::Camera);
    return "raylab: warning: " + std::string(frame ? "frame " + std::to_string(frame) + ": " : "") +
           std::to_string(r.cappedSamples) + " of " + std::to_string(samples) +
           " camera samples reached the cap of " + std::to_string(o.maxRaysPerSample) +
           " rays per sample; their deeper reflections and refractions were not traced "
           "(--max-rays, --depth)\n";
}

void printSummary(const RenderStats& s, const Film& film, const std::vector<std::string>& outputs) {
    const std::string crop = film.isCrop() ? " (crop " + std::to_string(film.width) + "x" +
                                                 std::to_string(film.height) + " at " +
                                                 std::to_string(film.originX) + "," +
                                                 std::to_string(film.originY) + ")"
                                           : "";
    std::printf("raylab: %dx%d%s, %d spp, depth %d, %s, %d threads, %llu primitives\n", s.width,
                s.height, crop.c_str(), s.spp, s.maxDepth, s.accel.c_str(), s.threads,
                (unsigned long long)s.primitives);
    std::string effects;
    for (const std::string& e : s.effects) effects += (effects.empty() ? "" : ", ") + e;
    std::printf("  effects:  %s\n", effects.empty() ? "(none: local shading only)" : effects.c_str());
    if (s.textures)
        std::printf("  textures: %llu (%.1f MiB), filter %s, footprint %s\n",
                    (unsigned long long)s.textures->count, s.textures->mebibytes,
                    s.textures->filter.c_str(), s.textures->footprint.c_str());
    std::printf("  time:     parse %.3f s, build %.3f s, render %.3f s, write %.3f s\n",
                s.parseSeconds, s.buildSeconds, s.renderSeconds, s.writeSeconds);
    std::printf("  rays:     camera %llu (hits %llu), shadow %llu, reflection %llu, refraction %llu\n",
                (unsigned long long)s.rays.total(RayType::Camera),
                (unsigned long long)s.rays.cameraHits,
                (unsigned long long)s.rays.total(RayType::Shadow),
                (unsigned long long)s.rays.total(RayType::Reflection),
                (unsigned long long)s.rays.total(RayType::Refraction));
    if (s.filter.attenuated > 0 || s.filter.cutOut > 0)
        std::printf("  filter:   %llu transmitter crossings dimmed shadow rays, %llu candidates cut out\n",
                    (unsigned long long)s.filter.attenuated, (unsigned long long)s.filter.cutOut);
    std::printf("  samples:  at most %llu rays in one sample, %llu capped at %llu\n",
                (unsigned long long)s.maxSampleRays, (unsigned long long)s.cappedSamples,
                (unsigned long long)s.maxRaysPerSample);
    std::printf("  speed:    %.2f Mrays/s\n", s.mraysPerSecond());
    std::string list;
    for (const std::string& o : outputs) list += (list.empty() ? "" : ", ") + o;
    std::printf("  output:   %s\n", list.c_str());
}

}  // namespace

int renderCommand(const std::vector<std::string>& args) {
    enterPhase(Phase::Parse);
    const RenderCli cli = parseRenderArgs(args);
    using Clock = std::chrono::steady_clock;
    // Under mpirun every rank runs this function: MPI starts here (never in
    // a plain run), all ranks render shares of each frame, rank 0 writes.
    const MpiSession mpi;
    // --threads N holds for the whole command, not only the render: loading,
    // the accelerator build and the output use at most N threads as well
    // (under mpirun the distributed renderer sets its own). Kept to the end
    // of the process (releaseAtExit below): lifting the limit makes TBB
    // start a worker that no work needs.
    std::unique_ptr<tbb::global_control> threadLimit;
    if (cli.overrides.threads && !mpi.active())
        threadLimit = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, size_t(*cli.overrides.threads));
    // TBB's workers allocate from malloc arenas of their own: on huge pages
    // too, as the main thread's heap (apps/heap_pages.h).
    useHugePageWorkerHeaps();

    auto t0 = Clock::now();
    const InputFileLog inputs;  // every file read from here on (input_files.h)
    Scene scene = loadSceneNamingFile(cli.scene, sceneLoadOptions(cli));
    if (cli.camera.any()) {
        try {
            scene.camera = scene.camera.overridden(cli.camera);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--eye/--look-at/--camera-up/--fov: ") + e.what());
        }
    }
    if (cli.triangulatePolygons) triangulatePolygons(scene);
    RenderStats stats;
    stats.parseSeconds = secondsSince(t0);

    RenderOptions options = resolveRenderOptions(scene, cli.overrides);
    // Only an EXR carries the AOV layers (depth, normal, albedo, objectId,
    // Cryptomatte): for PNG, JPEG, HDR or TIFF alone none is computed and the
    // film is RGBA alone (16 of an SPD film's 84 bytes per pixel). Under
    // mpirun the layers stay: the ranks' messages carry them.
    options.wantAovs = mpi.active() || std::any_of(cli.images.begin(), cli.images.end(),
                                                   [](const OutputFlag& image) {
                                                       return outputFormatOf(image.path) ==
                                                              OutputFormat::Exr;
                                                   });
    if (cli.crop) {
        options.crop = *cli.crop;
        const PixelWindow w = cropPixels(options.crop, options.width, options.height);
        if (w.empty())
            throw UsageError("--crop: the window holds no pixel of the " +
                             std::to_string(options.width) + "x" + std::to_string(options.height) +
                             " image (pixels ceil(X0*W)..ceil(X1*W)-1 and likewise in y)");
    }
    // Checked after the scene's own "render" block is merged: it may be the
    // one that turns adaptive sampling on.
    if (cli.overrides.spp && *cli.overrides.spp > 1 && (options.spd || options.adaptiveThreshold > 0))
        throw UsageError(std::string("--spp cannot be combined with ") +
                         (options.spd ? "--spd" : "adaptive supersampling (--adaptive or the scene's \"adaptive\")") +
                         ", which samples pixel corners instead");
    checkMemoryBudget(scene, options);
    // Every frame's camera is checked before the first frame renders.
    const std::optional<CameraPath> path =
        cli.frames ? std::optional<CameraPath>(sequenceCameraPath(scene, *cli.frames))
                   : std::nullopt;
    throwIfCancelled();

    const FrameRange frames = cli.frames.value_or(FrameRange{});
    // No output may be a file just read (a mesh, an MTL library, a numbered
    // frame name equal to the scene's), and one that cannot be written fails
    // now, not after a long render.
    checkOutputs(cli, inputs.files());
    if (mpi.isRoot()) {
        for (const OutputFlag& output : outputFlags(cli))
            if (!output.path.empty())
                checkWritable(cli.frames ? sequenceFileName(output.path, frames.first) : output.path);
        // JPEG, HDR and TIFF are written through OpenImageIO, EXRs of the
        // compressions raylab does not write itself through OpenEXR, each
        // loaded only for them: when it cannot be, say so now, not after the
        // render.
        for (const OutputFlag& image : cli.images) {
            const OutputFormat format = *outputFormatOf(image.path);
            if (format == OutputFormat::Exr)
                prepareExrWriter(image.path, cli.compression);
            else if (format != OutputFormat::Png)
                prepareOiioImageWriter(image.path, format);
        }
    }
    // Under mpirun every rank must render the same picture: rank 0 compares
    // what each one read and resolved. Every rank knows the verdict, so all of
    // them end normally (MPI finalised) and rank 0 alone says what differs.
    if (const std::string why = compareRanks(mpi, renderIdentity(cli.scene, inputs.files(), options,
                                                                 cli.frames, cli.triangulatePolygons));
        !why.empty()) {
        if (mpi.isRoot()) std::fprintf(stderr, "raylab: error: %s\n", terminalSafe(why).c_str());
        return 1;
    }

    enterPhase(Phase::Build);
    t0 = Clock::now();
    // Geometry the accelerator cannot take (beyond float range relative to
    // the eye) is a problem of the scene file: report it as such.
    std::unique_ptr<Accelerator> accel;
    try {
        accel = makeAccelerator(options.accel, scene, options.accelOptions);
    } catch (const std::exception& e) {
        throwIfCancelled();  // a cancelled Embree build reports RTC_ERROR_CANCELLED
        if (dynamic_cast<const std::invalid_argument*>(&e)) throw InputError(cli.scene, 0, e.what());
        throw;
    }
    throwIfCancelled();
    stats.buildSeconds = secondsSince(t0);

    const EffectSet effects = analyseEffects(scene, options);
    bool warnedCap = false;
    // Every frame of a sequence asks for the same buffers: the next one
    // takes back the mappings the last one freed instead of faulting in
    // fresh pages.
    const huge_pages::ReuseScope reuseFrameBuffers;
    for (int frame = frames.first; frame <= frames.last; ++frame) {
        // Sequences: out.exr -> out_0001.exr, ... (the BVH is built once).
        const auto output = [&](const std::string& file) {
            return cli.frames && !file.empty() ? sequenceFileName(file, frame) : file;
        };
        if (path) scene.camera = path->cameraAt(frame);
        enterPhase(Phase::Render);
        ProgressBar bar(cli.frames ? "frame " + std::to_string(frame) : "rendering",
                        !cli.quiet && mpi.isRoot() && isatty(STDERR_FILENO));
        DistributedReport report;
        const FilterCounts filterBefore = accel->filterCounts();
        RenderResult result = renderDistributed(mpi, scene, *accel, options, effects,
                                                [&](double f) { bar.update(f); }, &g_interrupted,
                                                &report);
        bar.finish();
        if (result.cancelled) {
            if (!mpi.isRoot()) claimExit();  // rank 0 alone reports
            return reportInterrupted();
        }
        if (!mpi.isRoot()) continue;  // the other ranks only render

        stats.rays = result.rays;
        stats.renderSeconds = result.renderSeconds;
        stats.primitives = scene.primitiveCount();
        stats.effects = effects.names();
        stats.threads = threadsPerRank(mpi, options);
        stats.accel = acceleratorName(options.accel);
        stats.width = options.width;
        stats.height = options.height;
        stats.spp = options.spp;
        stats.maxDepth = options.maxDepth;
        stats.nonFiniteSamples = result.nonFiniteSamples;
        stats.maxRaysPerSample = options.maxRaysPerSample;
        stats.cappedSamples = result.cappedSamples;
        stats.maxSampleRays = result.maxSampleRays;
        // Once per run (the statistics have every frame's count): a capped
        // sample lost part of its reflections and refractions.
        if (result.cappedSamples > 0 && !warnedCap) {
            warnedCap = true;
            std::fprintf(stderr, "%s", rayCapWarning(result, options, cli.frames ? frame : 0).c_str());
        }
        stats.filter = accel->filterCounts() - filterBefore;
        // The objects' names go to the EXR's Cryptomatte manifest and the
        // statistics only (SPD gears: 9,345 of them).
        std::vector<std::string> objectNames;
        if (options.wantAovs || !cli.stats.empty())
            for (const Object& object : scene.objects) objectNames.push_back(object.name);
        stats.objects.clear();
        if (!cli.stats.empty())
            for (size_t k = 0; k < objectNames.size(); ++k)
                stats.objects.push_back(matteName(objectNames, int(k)));
        if (effects.textures())
            stats.textures = RenderStats::Textures{
                textureFilterName(options.textures.filter),
                textureFootprintName(options.textures.footprint), scene.textures.size(),
                scene.textureBytes() / (1 << 20)};

        enterPhase(Phase::Write);
        t0 = Clock::now();
        // What defines the image, never how it was run (threads, output
        // names): the same render writes the same bytes.
        ExrOptions exr;
        exr.floatPixels = cli.floatPixels;
        exr.software = raylabSoftware();
        exr.settings = renderSettingsText(options);
        exr.alpha = alphaModeName(options.alpha);
        exr.compression = cli.compression;
        exr.spp = options.spp;
        exr.maxDepth = options.maxDepth;
        exr.threads = options.threads;
        exr.scenePath = cli.scene;
        exr.accel = acceleratorName(options.accel);
        exr.frame = cli.frames ? frame : 0;
        exr.camera = cameraMatrices(scene.camera, options.width, options.height);
        exr.objectNames = std::move(objectNames);  // its last use
        exr.matteRanks = matteRanksOfSampling(options);
        // A frame's files appear together or not at all: a failed PNG or
        // statistics write leaves an earlier render's EXR untouched too.
        AtomicFileGroup files(cli.fsync ? AtomicFileGroup::Durability::PowerLoss
                                        : AtomicFileGroup::Durability::ProcessCrash);
        std::vector<std::string> written;
        for (const OutputFlag& image : cli.images) {
            const std::string file = output(image.path);
            switch (*outputFormatOf(image.path)) {
                case OutputFormat::Exr: writeExr(file, result.film, exr, &files); break;
                case OutputFormat::Png: writePng(file, result.film, cli.exposure, &files); break;
                default:
                    writeOiioImage(file, result.film, *outputFormatOf(image.path), cli.exposure,
                                   raylabSoftware(), &files);
            }
            written.push_back(file);
        }
        stats.writeSeconds = secondsSince(t0);
        if (!cli.stats.empty()) writeFileAtomically(output(cli.stats), stats.toJson(), &files);
        enterPhase(Phase::Commit);
        files.commit();
        // What an interruption from now on leaves behind.
        if (frame == frames.last)
            setInterruptOutcome(cli.frames ? "every frame was written" : "the output was written");
        else
            setInterruptOutcome("frames " + std::to_string(frames.first) + " to " +
                                std::to_string(frame) + " written, " + std::to_string(frame + 1) +
                                " and later not");

        if (!cli.quiet) {
            printSummary(stats, result.film, written);
            std::fputs(formatLoadReport(report).c_str(), stdout);  // "" without mpirun
        }
    }
    // Every frame is committed: the scene and the accelerator go back to the
    // kernel with the process, not block by block (exit_keep.h).
    releaseAtExit(std::move(accel));
    releaseAtExit(std::move(scene));
    releaseAtExit(std::move(threadLimit));
    // A signal after the last commit still ends as interrupted (its line says
    // the files were written): a stop request is never ignored.
    if (cancelRequested() && mpi.isRoot()) return reportInterrupted();
    return 0;
}

}  // namespace raylab
