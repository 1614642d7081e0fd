#include "renderer/accel/embree_edge_hits.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace raylab {

namespace {

using Candidate = std::pair<uint32_t, uint32_t>;  ///< (object, triangle): the naive loop's order

struct Collector {
    const EdgeHitContext* ctx;
    std::vector<Candidate> found;
};

/// Called by rtcPointQuery for every primitive whose box reaches the query
/// sphere; keeps the triangles. Returns false: the query radius is unchanged.
bool collectTriangle(RTCPointQueryFunctionArguments* args) {
    auto& c = *static_cast<Collector*>(args->userPtr);
    const auto& geoms = *c.ctx->triangleGeoms;
    if (args->geomID == c.ctx->userGeomId || args->geomID >= geoms.size() ||
        !geoms[args->geomID])
        return false;
    const EmbreeTriangleGeometry& g = *geoms[args->geomID];
    c.found.emplace_back(g.object, g.triangle(args->primID));
    return false;
}

double maxAbs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

Hit resolveEdgeHit(const EdgeHitContext& ctx, const Ray& ray, double tMin, double tMax,
                   const Hit& hit) {
    // The hit point as Embree sees it, and a sphere around it wide enough for
    // the float error of Embree's t and of its boxes (about 6e-8 of the
    // coordinates' size) with a margin of 100: every triangle the double test
    // can give the hit to contains the exact point, so its box reaches it.
    const Vec3 rel = ray.o - ctx.origin;
    const Vec3 p = rel + ray.d * hit.t;
    const double radius = 1e-5 * (maxAbs(rel) + hit.t * maxAbs(ray.d));
    RTCPointQuery query;
    query.x = float(p.x);
    query.y = float(p.y);
    query.z = float(p.z);
    query.time = 0;
    query.radius = std::max(float(radius), 1e-30f);
    RTCPointQueryContext pqContext;
    rtcInitPointQueryContext(&pqContext);
    Collector collector{&ctx, {}};
    collector.found.reserve(16);
    rtcPointQuery(ctx.scene, &query, &pqContext, &collectTriangle, &collector);

    // The naive loop over the candidates: objects in scene order, triangles
    // in index order, each hit shrinking the interval, so the closest wins
    // and an exact tie goes to the earlier candidate.
    std::sort(collector.found.begin(), collector.found.end());
    collector.found.erase(std::unique(collector.found.begin(), collector.found.end()),
                          collector.found.end());
    std::optional<Hit> best;
    for (const auto& [object, prim] : collector.found) {
        const auto h = (*ctx.shapes)[object]->intersect(prim, ray, tMin, tMax, ctx.options);
        if (!h) continue;
        const Hit candidate{h->t, object, prim, h->u, h->v};
        // A single triangle is crossed once: a cut-out hit is no hit at all.
        if (ctx.filter->filters(object) && ctx.filter->cutOut(ray, candidate)) continue;
        tMax = h->t;
        best = candidate;
    }
    if (!best || (best->object == hit.object && best->prim == hit.prim)) return hit;
    return *best;
}

}  // namespace raylab
