#include "geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/plane_hit.h"
#include "geometry/quadratic.h"
#include "geometry/validate.h"

namespace raylab {

namespace {

/// Relative planarity tolerance (see Polygon::create).
constexpr double kPlanarityTolerance = 1e-5;
/// Below this |Newell| / diagonal² the vertices are treated as collinear.
constexpr double kCollinearTolerance = 1e-12;
/// Polygons with at least this many vertices get a PolygonGrid: below it the
/// watertight loop is short and a hit is likely to land in an edge cell.
constexpr size_t kGridMinVertices = 12;
/// Grid cells per vertex (a 144-gon gets ~9,200 cells, 2.3 KB): measured on SPD gears,
/// 16, 32 and 64 per vertex: render 293, 275, 263 M instructions (128x128), grid
/// building 33, 48, 75 M; at 512x512 64 costs least.
constexpr int kGridCellsPerVertex = 64;
/// The grid stands in for the watertight test only at scales where the
/// rounding of the shear and the plane hit stays relative (insideByGrid's
/// bound assumes it): every edge at least this long (in its largest
/// component; zero-length edges do not count), and the scale s of each
/// query (centroid, origin, hit) at most kGridMaxScale.
constexpr double kGridMinEdge = 0x1p-350;
constexpr double kGridMaxScale = 0x1p350;
/// Directions shorter than this (largest component) are left to the
/// watertight test: below it n·d's underflow is not covered by its bound.
constexpr double kGridMinDirection = 0x1p-900;
/// From this many vertices on, the watertight test finds the crossing edges
/// from bit masks; below it the plain loop is cheaper (measured on SPD balls'
/// floor quad: 110 instructions per test, 150 through masks).
constexpr size_t kMaskMinVertices = 16;
/// Vertices per chunk whose box can decide a whole byte of such a mask.
constexpr size_t kChunk = 8;
/// Chunk boxes are kept only while every coordinate, and the ray origins they
/// are used with, stay below this magnitude (double; 2^100 for float): then
/// the sheared y of a vertex, (Y - oy) - sy·(Z - oz) with |sy| <= 1, never
/// overflows, so no NaN can appear and rounding keeps its monotonicity.
constexpr double kChunkCoordLimit = 0x1p1000;
constexpr float kChunkCoordLimitF = 0x1p100f;

/// x = m·2^e exactly, m an integer of at most 53 bits (finite x; subnormals too).
struct ExactDouble {
    int64_t m;
    int e;
};
inline ExactDouble exactDouble(double x) {
    int e = 0;
    const double f = std::frexp(x, &e);  // x = f·2^e, 0.5 <= |f| < 1, exact
    return {static_cast<int64_t>(std::ldexp(f, 53)), e - 53};
}

/// Sign of ax·by - ay·bx for finite doubles, exact whatever the magnitudes:
/// each product is an integer of at most 106 bits times a power of two, and
/// the two are compared by their leading bit, then by their aligned bits.
int exactCrossSign(double ax, double ay, double bx, double by) {
    const ExactDouble a = exactDouble(ax), b = exactDouble(by), c = exactDouble(ay),
                      d = exactDouble(bx);
    const bool lNeg = (a.m < 0) != (b.m < 0), rNeg = (c.m < 0) != (d.m < 0);
    using U = unsigned __int128;
    U lm = U(a.m < 0 ? -a.m : a.m) * U(b.m < 0 ? -b.m : b.m);
    U rm = U(c.m < 0 ? -c.m : c.m) * U(d.m < 0 ? -d.m : d.m);
    int le = a.e + b.e, re = c.e + d.e;
    if (lm == 0 && rm == 0) return 0;
    if (rm == 0) return lNeg ? -1 : 1;
    if (lm == 0) return rNeg ? 1 : -1;
    if (lNeg != rNeg) return lNeg ? -1 : 1;  // l - r has l's sign
    const auto bits = [](U v) {
        const uint64_t hi = uint64_t(v >> 64);
        return hi ? 128 - __builtin_clzll(hi) : 64 - __builtin_clzll(uint64_t(v));
    };
    // Compare |l| with |r|: first by the position of the leading bit, then,
    // aligned to the larger exponent's scale (both below 2^107), bit for bit.
    int magnitude;
    const int lTop = bits(lm) + le, rTop = bits(rm) + re;
    if (lTop != rTop) {
        magnitude = lTop > rTop ? 1 : -1;
    } else {
        if (le > re) lm <<= (le - re); else rm <<= (re - le);
        magnitude = lm > rm ? 1 : (lm < rm ? -1 : 0);
    }
    return lNeg ? -magnitude : magnitude;
}

/// Exact sign of ax·by - ay·bx. The rounded value decides when it clears its
/// error bound; otherwise the difference of the two exact products (each a
/// double-word from twoProduct) is expanded exactly (Shewchuk's Two_Two_Diff)
/// and its most significant non-zero component gives the sign. twoProduct's
/// error term is exact only when its product neither underflows (below
/// 2^-969 it may lose bits) nor overflows: products outside that range take
/// exactCrossSign (float: the products are exact in double).
template <class T>
int crossSign(T ax, T ay, T bx, T by) {
    const T l = ax * by;
    const T r = ay * bx;
    const T det = l - r;
    const T bound = T(4) * std::numeric_limits<T>::epsilon() * (std::abs(l) + std::abs(r));
    if (det > bound) return 1;
    if (det < -bound) return -1;
    const bool finite = std::isfinite(ax) && std::isfinite(ay) && std::isfinite(bx) && std::isfinite(by);
    if (finite) {
        constexpr T kLow = std::is_same_v<T, float> ? 0x1p-100f : T(0x1p-960);
        constexpr T kHigh = std::is_same_v<T, float> ? 0x1p100f : T(0x1p1000);
        const auto safe = [&](T x, T y, T p) {
            return x == T(0) || y == T(0) || (std::abs(p) >= kLow && std::abs(p) <= kHigh);
        };
        if (!safe(ax, by, l) || !safe(ay, bx, r)) {
            if constexpr (std::is_same_v<T, float>) {
                const double d = double(ax) * double(by) - double(ay) * double(bx);
                return d > 0 ? 1 : (d < 0 ? -1 : 0);
            } else {
                return exactCrossSign(ax, ay, bx, by);
            }
        }
    }
    T el, er;
    twoProduct(ax, by, el);
    twoProduct(ay, bx, er);
    // (l + el) - (r + er) as the non-overlapping expansion x3 + x2 + x1 + x0.
    T lo0, x0, x1, x2;
    const T hi0 = twoSum(el, -er, x0);  // Two_One_Diff(l, el, er) -> (j, lo0, x0)
    const T j = twoSum(l, hi0, lo0);
    const T hi1 = twoSum(lo0, -r, x1);  // Two_One_Diff(j, lo0, r) -> (x3, x2, x1)
    const T x3 = twoSum(j, hi1, x2);
    for (T x : {x3, x2, x1, x0}) {
        if (x > T(0)) return 1;
        if (x < T(0)) return -1;
    }
    return 0;
}

/// The (u, v) axes of a polygon: t along its first edge projected onto the
/// plane (vertex 0 to the next vertex that differs from it), b = n × t.
Frame uvFrame(const std::vector<Vec3>& vertices, const Vec3& n) {
    for (size_t i = 1; i < vertices.size(); ++i) {
        const Vec3 e = vertices[i] - vertices[0];
        const Vec3 t = normalize(e - n * dot(n, e));
        if (lengthSquared(t) > 0.5) return Frame{t, cross(n, t), n};
    }
    return Frame::fromNormal(n);
}

}  // namespace

Vec3 newellNormal(const std::vector<Vec3>& vertices) {
    const size_t n = vertices.size();
    if (n == 0) return {};
    Vec3 mean{};
    for (const Vec3& v : vertices) mean += v;
    mean = mean / static_cast<double>(n);
    Vec3 sum{};
    for (size_t i = 0; i < n; ++i) {
        sum += cross(vertices[i] - mean, vertices[(i + 1) % n] - mean);
    }
    return sum;
}

Polygon::Polygon(std::vector<Vec3> vertices, std::vector<Vec3> normals, const Vec3& normal,
                 const Vec3& centroid, double deviation, FillRule rule, PolygonTest test)
    : m_frame(Frame::fromNormal(normal)),
      m_centroid(centroid),
      m_radius(0),
      m_deviation(deviation),
      m_count(vertices.size()),
      m_rule(rule),
      m_test(test),
      m_vertices(std::move(vertices)),
      m_normals(std::move(normals)),
      m_uvFrame(uvFrame(m_vertices, normal)),
      m_dropAxis(dominantAxis(normal)) {
    const size_t n = m_vertices.size();
    m_coords.resize(3 * n);
    m_coordsF.resize(3 * n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3& v = m_vertices[i];
        m_bounds.expand(v);
        for (size_t k = 0; k < 3; ++k) {
            m_coords[k * n + i] = v[int(k)];
            m_coordsF[k * n + i] = static_cast<float>(v[int(k)]);
        }
    }
    // Chunk boxes for the watertight test's masks (see aboveBits).
    if (n >= kMaskMinVertices) {
        const auto build = [&](const auto& coords, auto& lo, auto& hi, auto limit) {
            for (size_t k = 0; k < 3; ++k) {
                for (size_t c = 0; c < n; c += kChunk) {
                    const auto first = coords.begin() + std::ptrdiff_t(k * n + c);
                    const auto last = coords.begin() + std::ptrdiff_t(k * n + std::min(n, c + kChunk));
                    const auto [mn, mx] = std::minmax_element(first, last);
                    if (!(std::abs(*mn) <= limit && std::abs(*mx) <= limit)) {
                        lo = {};  // too large: every mask is computed vertex by vertex
                        hi = {};
                        return;
                    }
                    lo[k].push_back(*mn);
                    hi[k].push_back(*mx);
                }
            }
        };
        auto chunks = std::make_unique<ChunkBoxes>();
        build(m_coords, chunks->lo, chunks->hi, kChunkCoordLimit);
        build(m_coordsF, chunks->loF, chunks->hiF, kChunkCoordLimitF);
        m_chunks = std::move(chunks);
    }
    // The bounding rectangle in the (u, v) axes.
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi = lo * -1.0;
    for (const Vec3& v : m_vertices) {
        const Vec2 q{dot(v - m_centroid, m_uvFrame.t), dot(v - m_centroid, m_uvFrame.b)};
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
    }
    m_uvOrigin = lo;
    m_uvSize = hi - lo;
    // Hits lie on the centroid plane, up to `deviation` away from the vertices.
    m_bounds.lo -= Vec3{deviation, deviation, deviation};
    m_bounds.hi += Vec3{deviation, deviation, deviation};
    m_bounds = m_bounds.padded();

    for (const Vec3& v : m_vertices) m_radius = std::max(m_radius, length(v - m_centroid));
    if (m_vertices.size() >= kGridMinVertices && gridScale()) {
        std::vector<Vec2> plane;
        plane.reserve(m_vertices.size());
        for (const Vec3& v : m_vertices)
            plane.push_back({dot(v - m_centroid, m_frame.t), dot(v - m_centroid, m_frame.b)});
        // The clearance must exceed what rounding and the vertices' distance
        // from the plane can move a point (insideByGrid), yet stay far below
        // a cell: a millionth of the polygon, or 64 deviations.
        const double clearance = std::max(0x1p-20 * 2 * m_radius, 64 * m_deviation);
        auto grid = std::make_unique<PolygonGrid>(
            plane, m_rule, clearance, int(kGridCellsPerVertex * m_vertices.size()));
        // A grid that is all edge cells only costs time.
        if (grid->edgeFraction() < 0.75) m_grid = std::move(grid);
    }
}

bool Polygon::gridScale() const {
    if (!(maxComponent(abs(m_centroid)) + m_radius <= kGridMaxScale)) return false;
    for (size_t i = 0, n = m_vertices.size(); i < n; ++i) {
        const double e = maxComponent(abs(m_vertices[(i + 1) % n] - m_vertices[i]));
        if (e > 0 && e < kGridMinEdge) return false;
    }
    return true;
}

std::unique_ptr<Polygon> Polygon::create(const PolygonParams& params) {
    const auto& in = params.vertices;
    if (in.size() < 3) {
        throwInvalid("polygon",
                     "needs at least 3 vertices (got " + std::to_string(in.size()) + ")");
    }
    const bool hasNormals = !params.normals.empty();
    if (hasNormals && params.normals.size() != in.size()) {
        throwInvalid("polygon", std::to_string(params.normals.size()) + " vertex normals for " +
                                    std::to_string(in.size()) + " vertices");
    }
    for (size_t i = 0; i < in.size(); ++i) {
        if (!isFinite(in[i])) {
            throwInvalid("polygon", "vertex " + std::to_string(i) + " must be finite (got " +
                                        formatValue(in[i]) + ")");
        }
    }
    // Drop consecutive duplicates (a closing vertex repeating the first included).
    std::vector<Vec3> vertices;
    std::vector<Vec3> normals;
    vertices.reserve(in.size());
    if (hasNormals) normals.reserve(in.size());
    for (size_t i = 0; i < in.size(); ++i) {
        if (!vertices.empty() && in[i] == vertices.back()) continue;
        vertices.push_back(in[i]);
        if (hasNormals) {
            const std::string what = "normal of vertex " + std::to_string(i);
            normals.push_back(requireDirection("polygon", what.c_str(), params.normals[i]));
        }
    }
    while (vertices.size() > 1 && vertices.back() == vertices.front()) {
        vertices.pop_back();
        if (hasNormals) normals.pop_back();
    }
    if (vertices.size() < 3) {
        throwInvalid("polygon", "fewer than 3 distinct vertices (got " +
                                    std::to_string(vertices.size()) + ")");
    }

    Bounds3 box;
    double largest = 0;
    Vec3 centroid{};
    for (const Vec3& v : vertices) {
        box.expand(v);
        largest = std::max(largest, maxComponent(abs(v)));
        centroid += v;
    }
    centroid = centroid / static_cast<double>(vertices.size());
    const double diagonal = length(box.extent());

    Vec3 n = newellNormal(vertices);
    if (!(length(n) > kCollinearTolerance * diagonal * diagonal)) {
        // The signed areas may cancel (a bow-tie): fall back to the largest fan-free
        // triangle normal around the centroid; if that vanishes too, it is a line.
        Vec3 best{};
        for (size_t i = 0; i < vertices.size(); ++i) {
            const Vec3& next = vertices[(i + 1) % vertices.size()];
            const Vec3 c = cross(vertices[i] - centroid, next - centroid);
            if (lengthSquared(c) > lengthSquared(best)) best = c;
        }
        if (!(length(best) > kCollinearTolerance * diagonal * diagonal)) {
            throwInvalid("polygon", "vertices are collinear (zero area)");
        }
        n = best;
    }
    n = normalize(n);

    double deviation = 0;
    size_t worst = 0;
    for (size_t i = 0; i < vertices.size(); ++i) {
        const double dist = std::abs(dot(n, vertices[i] - centroid));
        if (dist > deviation) {
            deviation = dist;
            worst = i;
        }
    }
    const double tolerance = kPlanarityTolerance * (diagonal + largest);
    if (!(deviation <= tolerance)) {
        throwInvalid("polygon", "vertices are not coplanar (vertex " + std::to_string(worst) +
                                    " is " + formatValue(deviation) +
                                    " from the plane; tolerance " + formatValue(tolerance) + ")");
    }
    return std::make_unique<Polygon>(std::move(vertices), std::move(normals), n, centroid,
                                     deviation, params.rule, params.test);
}

Bounds3 Polygon::bounds() const { return m_bounds; }

bool Polygon::accepts(int winding, int crossings) const {
    return m_rule == FillRule::EvenOdd ? (crossings & 1) != 0 : winding != 0;
}

template <>
const double* Polygon::coords<double>(int axis) const {
    return m_coords.data() + size_t(axis) * m_count;
}

template <>
const float* Polygon::coords<float>(int axis) const {
    return m_coordsF.data() + size_t(axis) * m_count;
}

template <class T>
bool Polygon::insideProjected(const Vec3T<T>& p) const {
    // Drop the dominant axis of the normal; (X, Y) span the projection.
    const T* X = coords<T>((m_dropAxis + 1) % 3);
    const T* Y = coords<T>((m_dropAxis + 2) % 3);
    const T px = p[(m_dropAxis + 1) % 3];
    const T py = p[(m_dropAxis + 2) % 3];
    int winding = 0, crossings = 0;
    const size_t n = m_count;
    T ax = X[n - 1], ay = Y[n - 1];
    for (size_t i = 0; i < n; ++i) {
        const T bx = X[i], by = Y[i];
        // Sunday's isLeft: > 0 when p is left of the directed edge a -> b.
        if (ay <= py) {
            if (by > py && (bx - ax) * (py - ay) - (px - ax) * (by - ay) > T(0)) {
                ++winding;  // upward: includes start, excludes end
                ++crossings;
            }
        } else if (by <= py && (bx - ax) * (py - ay) - (px - ax) * (by - ay) < T(0)) {
            --winding;  // downward: excludes start, includes end
            ++crossings;
        }
        ax = bx;
        ay = by;
    }
    return accepts(winding, crossings);
}

namespace {

/// Bit i: whether vertex i's sheared y, (Y[i] - oy) - sy·(Z[i] - oz), is
/// > 0, for i < n <= 64 (insideWatertight's y; NaN is not > 0). Several
/// vertices per instruction where SSE2 is there: SIMD lanes round each
/// operation exactly as scalar code does (no FMA), so the bits are the same.
template <class T>
uint64_t aboveMask(const T* Y, const T* Z, size_t n, T oy, T oz, T sy) {
    uint64_t mask = 0;
    size_t i = 0;
#if defined(__SSE2__)
    if constexpr (std::is_same_v<T, double>) {
        const __m128d vy = _mm_set1_pd(oy), vz = _mm_set1_pd(oz), vs = _mm_set1_pd(sy);
        for (; i + 2 <= n; i += 2) {
            const __m128d y = _mm_sub_pd(_mm_sub_pd(_mm_loadu_pd(Y + i), vy),
                                         _mm_mul_pd(vs, _mm_sub_pd(_mm_loadu_pd(Z + i), vz)));
            mask |= uint64_t(_mm_movemask_pd(_mm_cmpgt_pd(y, _mm_setzero_pd()))) << i;
        }
    } else {
        const __m128 vy = _mm_set1_ps(oy), vz = _mm_set1_ps(oz), vs = _mm_set1_ps(sy);
        for (; i + 4 <= n; i += 4) {
            const __m128 y = _mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(Y + i), vy),
                                        _mm_mul_ps(vs, _mm_sub_ps(_mm_loadu_ps(Z + i), vz)));
            mask |= uint64_t(_mm_movemask_ps(_mm_cmpgt_ps(y, _mm_setzero_ps()))) << i;
        }
    }
#endif
    for (; i < n; ++i) mask |= uint64_t((Y[i] - oy) - sy * (Z[i] - oz) > T(0)) << i;
    return mask;
}

}  // namespace

template <class T>
bool Polygon::chunkBoxesUsable(T oy, T oz, T sy) const {
    const T limit = T(std::is_same_v<T, double> ? kChunkCoordLimit : kChunkCoordLimitF);
    const bool built = m_chunks && (std::is_same_v<T, double> ? !m_chunks->lo[0].empty()
                                                              : !m_chunks->loF[0].empty());
    // NaN fails every comparison, so it falls back to the vertex-by-vertex path.
    return built && std::abs(oy) <= limit && std::abs(oz) <= limit && std::abs(sy) <= T(1);
}

template <class T>
uint64_t Polygon::aboveBits(size_t base, size_t m, bool boxes, int ky, int kz, T oy, T oz,
                            T sy) const {
    const T* Y = coords<T>(ky) + base;
    const T* Z = coords<T>(kz) + base;
    if (!boxes) return aboveMask(Y, Z, m, oy, oz, sy);
    const std::array<std::vector<T>, 3>* lo;
    const std::array<std::vector<T>, 3>* hi;
    if constexpr (std::is_same_v<T, double>) {
        lo = &m_chunks->lo, hi = &m_chunks->hi;
    } else {
        lo = &m_chunks->loF, hi = &m_chunks->hiF;
    }
    // The sheared y, (Y - oy) - sy·(Z - oz), computed in rounded arithmetic,
    // is monotone in each input: rounding never reverses an order, so it grows
    // with Y and, as sy·(Z - oz) is subtracted, falls with Z when sy >= 0 and
    // grows with it when sy < 0. Evaluated the same way at a chunk box's
    // corners, it bounds exactly what every vertex of the chunk gets
    // (chunkBoxesUsable rules out overflow and NaN, which could break it). A
    // chunk whose lowest y is > 0 lies wholly above, one whose highest is <= 0
    // wholly below: only those the x axis passes near are computed vertex by
    // vertex.
    const std::vector<T>& yLo = (*lo)[ky];
    const std::vector<T>& yHi = (*hi)[ky];
    const std::vector<T>& zForLow = sy >= T(0) ? (*hi)[kz] : (*lo)[kz];
    const std::vector<T>& zForHigh = sy >= T(0) ? (*lo)[kz] : (*hi)[kz];
    uint64_t mask = 0;
    for (size_t k = 0; k < m; k += kChunk) {
        const size_t c = (base + k) / kChunk, len = std::min(kChunk, m - k);
        if ((yLo[c] - oy) - sy * (zForLow[c] - oz) > T(0)) {
            mask |= ((uint64_t(1) << len) - 1) << k;
        } else if ((yHi[c] - oy) - sy * (zForHigh[c] - oz) > T(0)) {
            mask |= aboveMask(Y + k, Z + k, len, oy, oz, sy) << k;
        }
    }
    return mask;
}

template <class T>
bool Polygon::insideWatertight(const Vec3T<T>& o, const Vec3T<T>& d, bool chunkBoxes) const {
    // Ray space: z = dominant |d| axis, shear so the ray is the +z axis through the origin.
    const int kz = dominantAxis(d);
    const int kx = (kz + 1) % 3;
    const int ky = (kx + 1) % 3;
    const T sx = d[kx] / d[kz];
    const T sy = d[ky] / d[kz];
    const T ox = o[kx], oy = o[ky], oz = o[kz];
    const T* X = coords<T>(kx);
    const T* Y = coords<T>(ky);
    const T* Z = coords<T>(kz);
    // A vertex's 2D coordinates depend only on the vertex and the ray: bit-identical
    // in every polygon sharing it.
    const auto shear = [&](size_t i, T& x, T& y) {
        const T wz = Z[i] - oz;
        x = (X[i] - ox) - sx * wz;
        y = (Y[i] - oy) - sy * wz;
    };
    int winding = 0, crossings = 0;
    // The edge a -> b, whose ends lie on opposite sides of the x axis.
    const auto crossingEdge = [&](T ax, T ay, T bx, T by) {
        const bool bAbove = by > T(0);
        // Evaluate lower endpoint -> upper endpoint, whichever way the polygon runs.
        const T lx = bAbove ? ax : bx, ly = bAbove ? ay : by;
        const T ux = bAbove ? bx : ax, uy = bAbove ? by : ay;
        int s = crossSign(lx, ly, ux, uy);  // > 0: origin left of the upward edge
        if (s == 0) {
            // Origin exactly on the edge's line: the perturbation decides,
            // orient = (ux - lx)·εy - (uy - ly)·εx with uy > ly.
            s = ux > lx ? 1 : -1;
        }
        if (s > 0) {  // the edge crosses the +x axis
            winding += bAbove ? 1 : -1;
            ++crossings;
        }
    };
    // Origin perturbed to (+εx, +εy): a vertex at y == 0 counts as below, and
    // only an edge with one end above and one below can cross the x axis.
    const size_t n = m_count;
    if (n < kMaskMinVertices) {
        T ax, ay;
        shear(n - 1, ax, ay);
        for (size_t i = 0; i < n; ++i) {
            T bx, by;
            shear(i, bx, by);
            if ((ay > T(0)) != (by > T(0))) crossingEdge(ax, ay, bx, by);
            ax = bx;
            ay = by;
        }
        return accepts(winding, crossings);
    }
    // Many vertices, few crossing edges (a 144-gon of SPD gears has a
    // handful): the sides of 64 vertices at a time make a bit mask, whose
    // changes from bit to bit are those edges.
    // Boxes of 8 vertices settle whole bytes of the mask (aboveBits).
    const bool boxes = chunkBoxes && chunkBoxesUsable(oy, oz, sy);
    uint64_t previous = aboveMask(Y + (n - 1), Z + (n - 1), 1, oy, oz, sy);  // the first edge's start
    for (size_t base = 0; base < n; base += 64) {
        const size_t m = std::min<size_t>(64, n - base);
        const uint64_t above = aboveBits(base, m, boxes, ky, kz, oy, oz, sy);
        uint64_t changes = above ^ ((above << 1) | previous);
        if (m < 64) changes &= (uint64_t(1) << m) - 1;
        for (; changes != 0; changes &= changes - 1) {
            const size_t b = base + size_t(__builtin_ctzll(changes)), a = b == 0 ? n - 1 : b - 1;
            T ax, ay, bx, by;
            shear(a, ax, ay);
            shear(b, bx, by);
            crossingEdge(ax, ay, bx, by);
        }
        previous = (above >> (m - 1)) & 1;
    }
    return accepts(winding, crossings);
}

int Polygon::insideByGrid(const Ray& ray, double t, double cosine, const Vec3& local) const {
    // The grid's answer is the watertight test's when every error stays below
    // the clearance. With H the exact plane hit and p = `local` (computed),
    // u = 2^-53, cos = |n·d|/|d|, S = |o - c| + |t||d| + radius:
    //  - |p - H| <= 20u·S/cos (t from two dot products; o + t·d; the frame's dots);
    //  - the watertight test shears every vertex relative to o, each sheared
    //    coordinate off by <= 10u·S; moving the vertices that little, or by
    //    their distance from the plane (<= deviation, <= 2·deviation after
    //    the shear), cannot change the winding number about the ray as long as
    //    every edge stays farther from it than that;
    //  - the shear maps plane distances to ray-space ones by a factor of at
    //    least cos/2 (its area factor |n·d|/|d_z| over its largest stretch 2).
    // So the answers agree when (46u·S + 4·deviation)/cos < clearance; the
    // test below uses 256u, bounds Euclidean norms by twice the largest
    // component, and lowers |n·d| by its own rounding error. NaN fails it.
    //
    // All of this assumes relative rounding in the shear, the plane hit and
    // the frame's dot products (crossSign's signs are exact for any finite
    // input). With every edge >= 2^-350 (the grid is built only then), so
    // S >= 2^-351, S <= 2^350 and |d| >= 2^-900, nothing overflows and an
    // underflow adds at most 2^-1074 per operation, far below the u·S and
    // u·|d| terms allowed for. Beyond that the watertight test answers alone.
    const double dMax = maxComponent(abs(ray.d));
    const double s = 2 * (maxComponent(abs(ray.o)) + maxComponent(abs(m_centroid)) +
                          std::abs(t) * dMax) + m_radius;
    if (!(s <= kGridMaxScale && dMax >= kGridMinDirection)) return -1;
    const double error = (256 * 0x1p-53 * s + 4 * m_deviation) * 2 * dMax;
    const double cosineLow = std::abs(cosine) - 16 * 0x1p-53 * dMax;
    // The zones about the centroid first (no load of the grid's cells). The
    // exact hit H lies in the plane within |local| + |p - H| of the centroid,
    // and no nearer than |local| - |p - H|: inside the inner disc every edge
    // is at least inner - |local| - |p - H| from H, beyond the outer circle
    // at least |local| - outer - |p - H| (each radius keeps a clearance in
    // hand, PolygonGrid::measureZones). The bound above covers |p - H| with
    // the vertices' own errors, as it does for a cell.
    const double r2 = dot(local, local);
    const double inner = m_grid->innerRadius(), outer = m_grid->outerRadius();
    if (r2 < inner * inner) {
        if (error < (inner - std::sqrt(r2)) * cosineLow)
            return m_grid->originCell() == PolygonGrid::Cell::Inside ? 1 : 0;
    } else if (r2 > outer * outer) {
        if (error < (std::sqrt(r2) - outer) * cosineLow) return 0;
    }
    const PolygonGrid::Cell cell = m_grid->at(dot(local, m_frame.t), dot(local, m_frame.b));
    if (cell == PolygonGrid::Cell::Edge) return -1;
    if (!(error < m_grid->clearance() * cosineLow)) return -1;
    return cell == PolygonGrid::Cell::Inside ? 1 : 0;
}

template <class T>
std::optional<ShapeHit> Polygon::intersectT(const Ray& ray, double tMin, double tMax,
                                            const IntersectOptions& opt) const {
    using V = Vec3T<T>;
    const V o(ray.o);
    const V d(ray.d);
    T t, cosine;
    // t relative to the centroid, subtracted in double before rounding to T.
    if (!intersectPlane(V(m_frame.n), V{}, V(ray.o - m_centroid), d, t, cosine)) return std::nullopt;
    if (!acceptsFacing(m_sides, cosine < T(0))) return std::nullopt;
    const double td = static_cast<double>(t);
    if (!(tMin < td && td < tMax)) return std::nullopt;
    const PolygonTest test = opt.polygonTest.value_or(m_test);
    const Vec3 local = ray.at(td) - m_centroid;
    bool inside;
    if (test == PolygonTest::Watertight) {
        // Large double-precision polygons first ask their grid (exact where it answers).
        const int byGrid = std::is_same_v<T, double> && m_grid && opt.polygonGrid
                               ? insideByGrid(ray, td, double(cosine), local)
                               : -1;
        inside = byGrid >= 0 ? byGrid == 1 : insideWatertight(o, d, opt.polygonChunkBoxes);
    } else {
        inside = insideProjected(o + d * t);
    }
    if (!inside) return std::nullopt;
    return ShapeHit{td, dot(local, m_frame.t), dot(local, m_frame.b)};
}

template std::optional<ShapeHit> Polygon::intersectT<float>(const Ray&, double, double,
                                                           const IntersectOptions&) const;
template std::optional<ShapeHit> Polygon::intersectT<double>(const Ray&, double, double,
                                                            const IntersectOptions&) const;

Vec3 Polygon::interpolatedNormal(const Vec3& p) const {
    // Mean-value coordinates (Floater 2003; signed angles per Hormann & Floater
    // 2006, valid for concave polygons): w_i = (tan(α_{i-1}/2) + tan(α_i/2)) / r_i
    // with α_i the signed angle at p between vertices i and i+1, and
    // tan(α/2) = (r_i r_{i+1} - s_i·s_{i+1}) / (n·(s_i × s_{i+1})), s_i = v_i - p.
    // Rolling over the edges keeps it allocation-free (it runs once per shading point).
    const size_t n = m_vertices.size();
    const double tiny = 1e-12 * length(m_bounds.extent());
    Vec3 sPrev = m_vertices[n - 1] - p;
    double rPrev = length(sPrev);
    double tanPrev = 0;
    Vec3 sum{};
    // Pass 0 computes tan(α_{n-1}/2) for the closing edge; passes 1..n accumulate.
    for (size_t pass = 0; pass <= n; ++pass) {
        const size_t i = pass % n;
        const Vec3 s = m_vertices[i] - p;
        const double r = length(s);
        if (!(r > tiny)) return m_normals[i];  // at a vertex
        const Vec3 c = cross(sPrev, s);
        const double d = dot(sPrev, s);
        if (length(c) <= 1e-12 * rPrev * r && d < 0) {
            // On the edge (i-1, i): linear interpolation along it.
            const size_t prev = (i + n - 1) % n;
            return (m_normals[prev] * r + m_normals[i] * rPrev) / (rPrev + r);
        }
        const double area = dot(m_frame.n, c);
        // area == 0 here means collinear on the same side: angle 0.
        const double tanCur = area != 0 ? (rPrev * r - d) / area : 0.0;
        if (pass > 0) {
            // tanPrev belongs to edge (i-2, i-1) and tanCur to edge (i-1, i): weight of i-1.
            const size_t prev = (i + n - 1) % n;
            sum += m_normals[prev] * ((tanPrev + tanCur) / rPrev);
        }
        tanPrev = tanCur;
        sPrev = s;
        rPrev = r;
    }
    return sum;
}

Vec3 Polygon::shadingNormal(const Vec3& p) const {
    if (m_normals.empty()) return m_frame.n;
    Vec3 ns = normalize(interpolatedNormal(p));
    if (!isFinite(ns) || ns == Vec3{}) return m_frame.n;
    return dot(ns, m_frame.n) < 0 ? -ns : ns;
}

SurfaceGeometry Polygon::surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const {
    SurfaceGeometry g;
    const Vec3 p = ray.at(hit.t);
    g.p = p - m_frame.n * dot(m_frame.n, p - m_centroid);
    g.ng = m_frame.n;
    g.ns = shadingNormal(g.p);
    g.frontFace = dot(ray.d, g.ng) < 0;
    if (detail != SurfaceDetail::Normals) {
        const Vec3 local = g.p - m_centroid;
        // A degenerate extent (never for a valid polygon) keeps u or v at 0.
        const auto scaled = [](double x, double size) { return size > 0 ? x / size : 0.0; };
        g.uv = {scaled(dot(local, m_uvFrame.t) - m_uvOrigin.x, m_uvSize.x),
                scaled(dot(local, m_uvFrame.b) - m_uvOrigin.y, m_uvSize.y)};
        g.dpdu = m_uvFrame.t * m_uvSize.x;
        g.dpdv = m_uvFrame.b * m_uvSize.y;
        if (!m_normals.empty()) {
            constexpr double h = 1e-6;  // in u, v: a millionth of the polygon
            g.dndu = (shadingNormal(g.p + g.dpdu * h) - shadingNormal(g.p - g.dpdu * h)) / (2 * h);
            g.dndv = (shadingNormal(g.p + g.dpdv * h) - shadingNormal(g.p - g.dpdv * h)) / (2 * h);
        }
    }
    return g;
}

std::unique_ptr<Shape> makePolygon(const PolygonParams& params) { return Polygon::create(params); }

}  // namespace raylab
