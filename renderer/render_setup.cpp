#include "renderer/render_setup.h"

#include <vector>

#include "renderer/film.h"
#include "renderer/io/errors.h"

namespace raylab {

namespace {

void apply(RenderOptions& r, const RenderOverrides& o) {
    if (o.spd) {
        r.spd = true;
        r.width = r.height = 512;
        r.maxDepth = 5;
        r.spp = 1;
        r.shadows = ShadowMode::Opaque;  // Haines' statistics count opaque feelers
    }
    if (o.width) r.width = *o.width;
    if (o.height) r.height = *o.height;
    if (o.spp) r.spp = *o.spp;
    if (o.maxDepth) r.maxDepth = *o.maxDepth;
    if (o.threads) r.threads = *o.threads;
    if (o.adaptiveThreshold) r.adaptiveThreshold = *o.adaptiveThreshold;
    if (o.adaptiveMaxLevel) r.adaptiveMaxLevel = *o.adaptiveMaxLevel;
    if (o.minWeight) r.minWeight = *o.minWeight;
    if (o.seed) r.seed = *o.seed;
    if (o.maxRaysPerSample) r.maxRaysPerSample = *o.maxRaysPerSample;
    if (o.accel) r.accel = *o.accel;
    if (o.bvhQuality) r.accelOptions.quality = *o.bvhQuality;
    if (o.robust) r.accelOptions.robust = *o.robust;
    if (o.precision) r.accelOptions.intersect.precision = *o.precision;
    if (o.polygonTest) r.accelOptions.intersect.polygonTest = *o.polygonTest;
    if (o.shadows) r.shadows = *o.shadows;
    if (o.alpha) r.alpha = *o.alpha;
    if (o.alphaCutoff) r.accelOptions.alphaCutoff = *o.alphaCutoff;
    if (o.epsilon) {
        r.spawn.mode = OffsetMode::FixedEpsilon;
        r.spawn.epsilon = *o.epsilon;
    }
    if (o.effects) r.forceAllEffects = *o.effects == EffectsMode::All;
    if (o.textureFilter) r.textures.filter = *o.textureFilter;
    if (o.textureFootprint) r.textures.footprint = *o.textureFootprint;
}

}  // namespace

RenderOptions resolveRenderOptions(const Scene& scene, const RenderOverrides& o) {
    RenderOptions r;
    r.width = scene.image.width;
    r.height = scene.image.height;
    r.spp = scene.image.spp;
    r.maxDepth = scene.image.maxDepth;
    apply(r, scene.settings);
    apply(r, o);
    // Adaptive supersampling and the SPD procedure trace pixel corners, not
    // spp samples per pixel: record what is done (EXR header, statistics).
    if (r.spd || r.adaptiveThreshold > 0) r.spp = 1;
    // Geometry goes to Embree in float relative to the eye (camera-relative
    // rendering), and secondary-ray offsets are scaled in the same frame.
    r.accelOptions.origin = scene.camera.frame().eye;
    r.spawn.reference = scene.camera.frame().eye;
    return r;
}

size_t acceleratorEntries(const Scene& scene, const IntersectOptions& opt) {
    size_t n = 0;
    std::vector<Bounds3> boxes;
    for (const Object& o : scene.objects) {
        if (!o.shape) continue;
        if (o.shape->nativeTriangles()) {
            n += o.shape->primitiveCount();
            continue;
        }
        for (uint32_t prim = 0; prim < o.shape->primitiveCount(); ++prim) {
            boxes.clear();
            o.shape->appendCoveringBoxes(prim, opt, boxes);
            n += boxes.size();
        }
    }
    return n;
}

MemoryEstimate estimateRenderMemory(int width, int height, size_t entries) {
    MemoryEstimate e;
    // RGBA, Z, distance, N, albedo, objectId floats and the Cryptomatte ranks.
    e.filmBytes = double(width) * double(height) *
                  ((4 + 1 + 1 + 3 + 3 + 1) * sizeof(float) + kMatteRanks * sizeof(MatteEntry)) * 2.0;
    e.accelBytes = double(entries) * 128.0;
    return e;
}

void checkMemoryBudget(const Scene& scene, const RenderOptions& options) {
    checkMemoryBudget(scene, options, tightestMemoryLimit(readMemoryFacts()));
}

void checkMemoryBudget(const Scene& scene, const RenderOptions& options,
                       const std::optional<MemoryLimit>& limit) {
    if (!limit) return;  // nothing known: no need to walk the scene's primitives
    const size_t primitives = scene.primitiveCount();
    const MemoryEstimate e =
        estimateRenderMemory(options.width, options.height,
                             acceleratorEntries(scene, options.accelOptions.intersect));
    if (e.total() <= limit->bytes) return;
    const std::string image =
        "a " + std::to_string(options.width) + "x" + std::to_string(options.height) + " image";
    const std::string what =
        e.accelBytes < 0.01 * e.total()
            ? image + " needs about " + describeBytes(e.total())
            : image + " of " + std::to_string(primitives) + " primitives needs about " +
                  describeBytes(e.total()) + " (film " + describeBytes(e.filmBytes) +
                  ", acceleration structure " + describeBytes(e.accelBytes) + ")";
    // Point at the file's image size when that is what the render uses.
    const bool sizeFromFile =
        options.width == scene.image.width && options.height == scene.image.height;
    throw InputError(scene.sourcePath, sizeFromFile ? scene.image.sizeLine : 0,
                     what + ", more than the " + describeBytes(limit->bytes) + " that " + limit->source);
}

}  // namespace raylab
