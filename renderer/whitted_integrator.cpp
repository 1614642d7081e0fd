#include "renderer/whitted_integrator.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <optional>
#include <utility>

#include "geometry/spawn.h"
#include "renderer/cancel.h"
#include "renderer/late_value.h"
#include "shading/brdf.h"
#include "shading/optics.h"
#include "shading/radiance_range.h"

namespace raylab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The diffuse reflectance at a hit: kd times the surface's colour (a mesh's
/// vertex colours; white, which leaves kd as it is, everywhere else), kd
/// already textured for textured materials.
Color diffuseAt(const SurfaceInteraction& si, const SurfaceOptics& m) {
    return m.kd * Color(si.color.x, si.color.y, si.color.z);
}

}  // namespace

template <unsigned... E>
constexpr auto WhittedIntegrator::kernelTable(std::integer_sequence<unsigned, E...>) {
    return std::array<Kernel, sizeof...(E)>{&WhittedIntegrator::start<E>...};
}

WhittedIntegrator::WhittedIntegrator(const Scene& scene, const Accelerator& accel,
                                     const RenderOptions& options, const EffectSet& effects)
    : m_scene(scene), m_accel(accel), m_options(options), m_effects(effects) {
    // The general kernel traces every ray type at every hit, zero weights
    // included; SPD's procedure traces zero-weight reflection rays too.
    m_prune = !options.forceAllEffects;
    m_shadowHints = m_effects.has(kShadows) && accel.usesOcclusionHints(m_effects.filteredShadows);
    // Feelers of camera hits in packets (prepareCameraHits). With the shadow
    // cache in use only where triangles outnumber the analytic primitives:
    // the cache names analytic occluders alone, and where they are the bulk
    // of a scene its guesses, one at a time, beat packets (whole process,
    // one thread, 9-15 rounds: balls, gears, rings --spd 0.948, 0.951,
    // 0.941x with packets; the demo with opaque shadows 1.018x, mount 1.004x;
    // docs/benchmarks.md, session 2026-12-06 18:09).
    size_t triangles = 0;
    for (const Object& o : scene.objects)
        if (o.shape && o.shape->nativeTriangles()) triangles += o.primitiveCount();
    const bool mostlyTriangles = 2 * triangles > scene.primitiveCount();
    m_prepareHits = m_effects.has(kShadows) && !m_effects.textures() && accel.tracesPackets() &&
                    (!m_shadowHints || mostlyTriangles);
    // One instantiation of trace<E> per effect combination, chosen once here.
    constexpr unsigned kKernels = 2 * kTextures;
    static constexpr auto table = kernelTable(std::make_integer_sequence<unsigned, kKernels>());
    m_kernel = table[m_effects.kernel & (kKernels - 1)];
    if (m_effects.textures()) m_textures = std::make_unique<TextureShading>(scene, options);
    // Departures rest on the robust offset keeping a spawned ray's start off
    // its surface, to the side it leaves into, and on the exact double test
    // seeing it so; a fixed epsilon or float intersectors may meet their own
    // surface again (the acne the accuracy study measures).
    const bool departures = options.departures && options.spawn.mode == OffsetMode::Robust &&
                            options.accelOptions.intersect.precision == Precision::Double;
    m_revisit.assign(scene.objects.size(), Revisit::Any);
    if (departures)
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const Shape* shape = scene.objects[i].shape.get();
            if (shape && shape->primitiveCount() == 1) m_revisit[i] = shape->revisit();
        }
}

WhittedIntegrator::~WhittedIntegrator() = default;

double WhittedIntegrator::cameraTMin(const Ray& cameraRay) const {
    // No near plane (JSON scenes' default): 0 / along would be this same +0,
    // at the cost of a division per camera ray.
    if (m_scene.cameraNear == 0 && !std::signbit(m_scene.cameraNear)) return 0.0;
    const double along = -dot(cameraRay.d, m_scene.camera.frame().w);
    return along > 0 ? m_scene.cameraNear / along : 0.0;
}

Color WhittedIntegrator::Li(const Ray& cameraRay, RayCounters& counters, FirstHit* first,
                            SampleRays& spent, ShadowCache* shadows,
                            const std::optional<Hit>* cameraHit,
                            const PreparedHit* prepared) const {
    if (!m_shadowHints) shadows = nullptr;
    if (shadows) shadows->prepare(m_scene.objects.size(), m_scene.lights.size(), m_options.maxDepth);
    TraceState state{counters, shadows, spent};
    // A given camera hit was asked with cameraHits' own near distance: start
    // has no use for another.
    const double tNear = cameraHit ? 0.0 : cameraTMin(cameraRay);
    return (this->*m_kernel)(cameraRay, tNear, state, first, cameraHit, prepared);
}

void WhittedIntegrator::cameraHits(const Ray* rays, int count, std::optional<Hit>* out) const {
    double tMin[Accelerator::kPacketRays], tMax[Accelerator::kPacketRays];
    for (int i = 0; i < count; ++i) {
        tMin[i] = cameraTMin(rays[i]);
        tMax[i] = kInf;  // as trace asks
    }
    m_accel.intersectPacket(rays, tMin, tMax, count, out);
}

[[gnu::always_inline]] inline void WhittedIntegrator::lightTerms(
    LightTerms& t, bool highlights, const SurfaceOptics& m, const Color& diffuse,
    const Color& arriving, const Vec3& n, const Vec3& l, double nDotL, const Vec3& toViewer) const {
    t.diffuse = lambert(diffuse, arriving, nDotL);
    t.highlighted = highlights && (!m_prune || !m.ks.isBlack());
    if (t.highlighted)
        t.highlight = m.highlight == Highlight::Phong
                          ? phong(m.ks, m.shininess, arriving, n, l, toViewer)
                          : blinnPhong(m.ks, m.shininess, arriving, n, l, toViewer);
}

namespace {

/// Adds a light's terms to `result` in LightTerms' order.
void addTerms(Color& result, const LightTerms& t) {
    result += t.diffuse;
    if (t.highlighted) result += t.highlight;
}

}  // namespace

void WhittedIntegrator::prepareCameraHits(const Ray* rays, const std::optional<Hit>* hits,
                                          int count, PreparedHits& out,
                                          ShadowCache* shadows) const {
    const size_t lights = m_scene.lights.size();
    out.clear(m_prepareHits ? lights : 0);  // no feelers' room where none will be kept
    if (!m_prepareHits) return;
    if (!m_shadowHints) shadows = nullptr;
    if (shadows) shadows->prepare(m_scene.objects.size(), lights, m_options.maxDepth);
    constexpr int K = Accelerator::kPacketRays;
    // Each hit as traceHit sees it (untextured kernels: normals only).
    Vec3 normals[K];  // on the side the ray arrives from
    bool feels[K];    // shadeLocal traces feelers from this hit
    Color diffuse[K];  // its diffuse reflectance, where it does
    // The records first, then what is read from them: read right after the
    // call that wrote it, a record was read across its stores, and the
    // reads waited for the stores to reach the cache.
    PreparedHit* prepared[K];
    for (int k = 0; k < count; ++k) {
        if (!hits[k]) continue;
        PreparedHit& h = *(prepared[k] = &out.prepare(k));
        h.dir = normalize(rays[k].d);
        rebuildInPlace(h.si, [&] {
            return m_scene.surfaceAt(rays[k], *hits[k], m_options.accelOptions.intersect,
                                     SurfaceDetail::Normals);
        });
    }
    for (int k = 0; k < count; ++k) {
        feels[k] = false;
        if (!hits[k]) continue;
        PreparedHit& h = *prepared[k];
        const SurfaceInteraction& si = h.si;
        normals[k] = si.frontFace ? si.ns : -si.ns;
        h.spawn.emplace(si.p, si.frontFace ? si.ng : -si.ng, si.span, m_options.spawn);
        const SurfaceOptics& m = m_scene.materials[si.material];
        feels[k] = shadesLocally(m);
        if (feels[k]) diffuse[k] = diffuseAt(si, m);
    }
    // Per light, the feelers shadeLocal would trace, in one packet.
    Ray feelers[K];
    double tMin[K], tMax[K];
    Departure from[K];
    int lane[K];
    Color answers[K];
    OcclusionHint hints[K];
    ShadowCache::Slots slots[K];  // where each feeler's answer goes in the cache
    for (size_t li = 0; li < lights; ++li) {
        int n = 0;
        for (int k = 0; k < count; ++k) {
            if (!feels[k]) continue;
            const PreparedHit& h = *out.lane(k);
            const SurfaceInteraction& si = h.si;
            const auto [toLight, reach] = towards(m_scene.lights[li], si.p);
            PreparedFeeler& f = out.feelers(k)[li];  // as shadeLocal computes them
            f.l = normalize(toLight);
            f.nDotL = dot(normals[k], f.l);
            if (m_prune && !(f.nDotL > 0)) continue;
            feelers[n].o = h.spawn->origin(toLight);  // the parts in place (see RaySpawner)
            feelers[n].d = toLight;
            tMin[n] = h.spawn->tMin(toLight);
            tMax[n] = reach;
            from[n] = departure(si, toLight);
            if (shadows) {  // the guesses shadeLocal would take (a camera hit is at depth 1)
                slots[n] = ShadowCache::slots(shadows->receiver(si.object, 1), li);
                hints[n] = slots[n].hint();
            }
            lane[n++] = k;
        }
        if (n == 0) continue;
        m_accel.shadowPacket(feelers, tMin, tMax, from, n, m_effects.filteredShadows, answers,
                             shadows ? hints : nullptr);
        // The terms of the lights that arrive, lane after lane: the square
        // roots and divisions of neighbouring hits overlap, where in each
        // ray tree they would wait for the work before them.
        const Light& light = m_scene.lights[li];
        for (int j = 0; j < n; ++j) {
            if (shadows) slots[j].remember(hints[j]);
            const int k = lane[j];
            PreparedFeeler& f = out.feelers(k)[li];
            f.through = answers[j];
            f.lit = !f.through.isBlack() && f.nDotL > 0;
            if (!f.lit) continue;
            const PreparedHit& h = *out.lane(k);
            const Color arriving =
                m_effects.filteredShadows ? arrivingThrough(light, f.through) : light.intensity;
            // Written in place: a returned record, copied, was read back
            // across its stores (a stall in the profile).
            lightTerms(f.terms, m_effects.has(kHighlights), m_scene.materials[h.si.material],
                       diffuse[k], arriving, normals[k], f.l, f.nDotL, -h.dir);
        }
    }
}

bool WhittedIntegrator::mayBranch(SampleRays& spent) const {
    // A stop request ends even a ray tree of depth 64 within one ray (the
    // pixel loops check only between pixels).
    if (cancelRequested()) return false;
    // The cap bounds the work of one sample; the rays are counted in the
    // sample's own depth-first order, so the cut falls at the same ray for
    // any thread count.
    if (spent.traced < m_options.maxRaysPerSample) return true;
    spent.capped = true;
    return false;
}

template <unsigned E>
Color WhittedIntegrator::start(const Ray& cameraRay, double tNear, TraceState& state,
                               FirstHit* first, const std::optional<Hit>* cameraHit,
                               const PreparedHit* prepared) const {
    // No footprint yet: trace computes the camera ray's at its hit (a miss
    // needs none) from the unit direction it has there.
    if (!cameraHit)
        return trace<E>(cameraRay, tNear, Departure{}, 1, RayType::Camera, 1.0, state, first, nullptr);
    countRay(state, RayType::Camera, 1);
    return traceHit<E>(cameraRay, *cameraHit, 1, RayType::Camera, 1.0, state, first, nullptr,
                       prepared);
}

template <unsigned E>
Color WhittedIntegrator::shadeLocal(const SurfaceInteraction& si, const SurfaceOptics& m,
                                    const Vec3& n, const RaySpawner& spawn, const Vec3& toViewer,
                                    int depth, TraceState& state,
                                    const PreparedFeeler* answered) const {
    // Radiance saturates at the largest double (shading/radiance_range.h):
    // an overflow is as bright as can be, never Inf, never NaN, never black.
    const Color ka = m.ambientFollowsDiffuse ? diffuseAt(si, m) : m.ka;
    Color result = saturated(ka * m_scene.ambient);  // ambient once, kept in shadow
    if constexpr ((E & kShadows) == 0) {
        return result;
    } else {
        if (!shadesLocally(m)) return result;
        // No shadow ray when the normal faces away from the light. The
        // general kernel traces it anyway and then adds nothing, so both
        // kernels produce the same image.
        if (answered) {  // prepareCameraHits traced the feelers and has the terms
            for (size_t li = 0; li < m_scene.lights.size(); ++li) {
                const PreparedFeeler& f = answered[li];
                if (m_prune && !(f.nDotL > 0)) continue;
                state.counters.count(RayType::Shadow, depth + 1);
                ++state.spent.traced;
                if (f.lit) addTerms(result, f.terms);
            }
            return saturated(result);  // the terms are >= 0: once Inf, the sum stays Inf
        }
        const Color diffuse = diffuseAt(si, m);
        constexpr bool kHighlighted = (E & kHighlights) != 0;
        ShadowCache::Receiver receiver{};
        if (state.shadows) receiver = state.shadows->receiver(si.object, depth);
        for (size_t li = 0; li < m_scene.lights.size(); ++li) {
            const Light& light = m_scene.lights[li];
            const auto [toLight, tMax] = towards(light, si.p);
            const Vec3 l = normalize(toLight);
            const double nDotL = dot(n, l);
            const bool facing = nDotL > 0;
            if (m_prune && !facing) continue;
            state.counters.count(RayType::Shadow, depth + 1);
            ++state.spent.traced;
            const SpawnedRay shadow = spawn(toLight);
            const Departure from = departure(si, toLight);
            // The occluders of earlier feelers from this surface are this
            // one's first guesses (shadow_cache.h): less work, the same answer.
            OcclusionHint hint;
            ShadowCache::Slots slots{};
            if (state.shadows) {
                slots = ShadowCache::slots(receiver, li);
                hint = slots.hint();
            }
            // Filtered shadows: the light arrives dimmed by the transmitters
            // on the way (no refraction of the feeler: an approximation).
            if (m_effects.filteredShadows) {
                const Color through =
                    state.shadows ? m_accel.transmittance(shadow.ray, shadow.tMin, tMax, from, hint)
                                  : m_accel.transmittance(shadow.ray, shadow.tMin, tMax, from);
                if (state.shadows) slots.remember(hint);
                if (through.isBlack() || !facing) continue;
                LightTerms terms;
                lightTerms(terms, kHighlighted, m, diffuse, arrivingThrough(light, through), n, l,
                           nDotL, toViewer);
                addTerms(result, terms);
            } else {
                const bool blocked =
                    state.shadows ? m_accel.occluded(shadow.ray, shadow.tMin, tMax, from, hint)
                                  : m_accel.occluded(shadow.ray, shadow.tMin, tMax, from);
                if (state.shadows) slots.remember(hint);
                if (blocked || !facing) continue;
                LightTerms terms;
                lightTerms(terms, kHighlighted, m, diffuse, light.intensity, n, l, nDotL, toViewer);
                addTerms(result, terms);
            }
        }
        return saturated(result);  // the terms are >= 0: once Inf, the sum stays Inf
    }
}

template <unsigned E>
Color WhittedIntegrator::trace(const Ray& ray, double tMin, Departure from, int depth,
                               RayType type, double weight, TraceState& state, FirstHit* first,
                               const Footprint<E>* carried) const {
    countRay(state, type, depth);
    return traceHit<E>(ray, m_accel.intersect(ray, tMin, kInf, from), depth, type, weight, state,
                       first, carried, nullptr);
}

template <unsigned E>
Color WhittedIntegrator::traceHit(const Ray& ray, const std::optional<Hit>& hit, int depth,
                                  RayType type, double weight, TraceState& state, FirstHit* first,
                                  const Footprint<E>* carried, const PreparedHit* prepared) const {
    if (!hit) return m_scene.background;
    if (type == RayType::Camera) state.counters.cameraHits++;

    // Textured scenes need the surface derivatives at every hit (footprints),
    // uv only where the material has maps.
    SurfaceDetail detail = SurfaceDetail::Normals;
    [[maybe_unused]] bool hasMaps = false;  // the hit's material has texture maps
    if constexpr (textured(E)) {
        hasMaps = m_scene.materials[m_scene.objects[hit->object].materialOf(hit->prim)].maps.any();
        detail = hasMaps ? SurfaceDetail::Complete : SurfaceDetail::Derivatives;
    }
    // A prepared camera hit (untextured kernels) comes with its record, read
    // in place (a copy showed in the profile).
    LateValue<SurfaceInteraction> ownRecord;
    SurfaceInteraction* own =
        prepared ? nullptr : &ownRecord.emplaceFrom([&] {
            return m_scene.surfaceAt(ray, *hit, m_options.accelOptions.intersect, detail);
        });
    const SurfaceInteraction& si = own ? *own : prepared->si;
    // `entering` is false when the ray is inside the object (it hit the back
    // of the outward normal).
    const bool entering = si.frontFace;
    const Vec3 dir = prepared ? prepared->dir : normalize(ray.d);
    const SurfaceOptics* optics = &m_scene.materials[si.material];
    // The footprint the ray carries; a camera ray's (carried == nullptr) is
    // computed here, where normalize(ray.d) is known (LateValue: nothing is
    // built or zeroed on the other rays).
    [[maybe_unused]] LateValue<Footprint<E>> cameraFootprint;
    if constexpr (textured(E))
        if (!carried)
            carried = &cameraFootprint.emplaceFrom([&] { return m_textures->cameraFootprint(ray, dir); });
    // The hit's footprint, built in place (a default record would be zeroed
    // first at every hit). Untextured materials pass the footprint on too (a
    // plain mirror showing a textured object).
    [[maybe_unused]] const HitFootprintOf<E> hitFootprint = [&]() -> HitFootprintOf<E> {
        if constexpr (textured(E))
            return m_textures->atHit(*carried, ray, dir, si.t, si);
        else
            return {};
    }();
    [[maybe_unused]] LateValue<SurfaceOptics> texturedOptics;
    if constexpr (textured(E)) {
        if (hasMaps)
            optics = &texturedOptics.emplaceFrom(
                // `own` is set: prepared hits are untextured (m_prepareHits).
                [&] { return m_textures->shade(si.material, *own, hitFootprint); });
    }
    const SurfaceOptics& m = *optics;
    // Normals on the side the ray arrives from.
    const Vec3 n = entering ? si.ns : -si.ns;
    const Vec3 ng = entering ? si.ng : -si.ng;

    if (first) {
        first->hit = true;  // the pixel's coverage (alpha) needs it always
        if (m_options.wantAovs) {  // the layers only where an output carries them
            first->distance = float(std::min(hit->t * length(ray.d), double(FLT_MAX)));
            first->normal = si.ns;
            first->albedo = diffuseAt(si, m);
            first->objectId = float(si.object);
        }
    }

    // One offset for all of this hit's rays (a prepared hit's is made).
    LateValue<RaySpawner> ownSpawn;
    const RaySpawner& spawn =
        prepared ? *prepared->spawn
                 : ownSpawn.emplace(si.p, ng, si.span, m_options.spawn);
    Color result =
        shadeLocal<E>(si, m, n, spawn, -dir, depth, state, prepared ? prepared->feelers : nullptr);
    if (depth >= m_options.maxDepth) return result;

    constexpr bool kAnySecondary = (E & (kReflection | kRefraction)) != 0;
    if constexpr (kAnySecondary) {
        // Refraction first: total internal reflection hands its energy to the
        // mirror ray, so both weights are known before any ray is traced.
        Color reflectWeight = m.km;
        bool traceReflection = false;
        if constexpr ((E & kReflection) != 0) {
            traceReflection = !m_prune || m.reflective() ||
                              (m_options.spd && (!m.ks.isBlack() || m.transmissive()));
        }
        if constexpr ((E & kRefraction) != 0) {
            if (!m_prune || m.transmissive()) {
                const double etaI = entering ? 1.0 : m.ior;
                const double etaT = entering ? m.ior : 1.0;
                const std::optional<Vec3> t = refract(dir, n, etaI, etaT);
                if (t) {
                    const double w = saturated(weight * m.kt.maxComponent());
                    if ((!m_prune || m_options.spd || w >= m_options.minWeight) && mayBranch(state.spent)) {
                        const SpawnedRay r = spawn(*t);
                        const Footprint<E> next = [&]() -> Footprint<E> {
                            if constexpr (textured(E))
                                return m_textures->refracted(*carried, hitFootprint, si, entering, dir,
                                                             n, *t, etaI / etaT);
                            else
                                return {};
                        }();
                        result += m.kt * trace<E>(r.ray, r.tMin, departure(si, *t), depth + 1,
                                                  RayType::Refraction, w, state, nullptr, &next);
                    }
                } else {
                    reflectWeight = saturated(reflectWeight + m.kt);  // total internal reflection
                    traceReflection = traceReflection || m.transmissive() || !m_prune;
                }
            }
        }
        if (traceReflection) {
            const double w = saturated(weight * reflectWeight.maxComponent());
            if ((!m_prune || (w > 0 && w >= m_options.minWeight) || m_options.spd) &&
                mayBranch(state.spent)) {
                const Vec3 r = reflect(dir, n);
                const SpawnedRay s = spawn(r);
                const Footprint<E> next = [&]() -> Footprint<E> {
                    if constexpr (textured(E))
                        return m_textures->reflected(*carried, hitFootprint, si, entering, dir, n);
                    else
                        return {};
                }();
                result += reflectWeight * trace<E>(s.ray, s.tMin, departure(si, r), depth + 1,
                                                   RayType::Reflection, w, state, nullptr, &next);
            }
        }
    }
    // Finite weights times finite radiance, all >= 0: at worst +Inf, saturated.
    return saturated(result);
}

}  // namespace raylab
