#include "geometry/polygon_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace raylab {

namespace {

/// Whether segment a-b meets the box [lo, hi] (Liang-Barsky clipping).
bool segmentMeetsBox(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi) {
    double t0 = 0, t1 = 1;
    const double d[2] = {b.x - a.x, b.y - a.y};
    const double p[2] = {a.x, a.y};
    const double l[2] = {lo.x, lo.y}, h[2] = {hi.x, hi.y};
    for (int k = 0; k < 2; ++k) {
        if (d[k] == 0) {
            if (p[k] < l[k] || p[k] > h[k]) return false;
            continue;
        }
        double ta = (l[k] - p[k]) / d[k], tb = (h[k] - p[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

/// Distance from the origin to segment a-b.
double originDistance(const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const double ee = e.x * e.x + e.y * e.y;
    const double f = ee > 0 ? std::clamp(-(a.x * e.x + a.y * e.y) / ee, 0.0, 1.0) : 0.0;
    const Vec2 p = a + e * f;
    return std::sqrt(p.x * p.x + p.y * p.y);
}

}  // namespace

PolygonGrid::PolygonGrid(const std::vector<Vec2>& vertices, FillRule rule, double clearance,
                         int cells)
    : m_clearance(clearance) {
    Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec2 hi = lo * -1.0;
    for (const Vec2& p : vertices) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    // Points beyond the grid are outside: it reaches past every vertex by
    // more than the clearance.
    const double margin = 2 * clearance;
    lo = lo - Vec2{margin, margin};
    hi = hi + Vec2{margin, margin};
    const double w = hi.x - lo.x, h = hi.y - lo.y;
    // Roughly square cells, `cells` of them.
    const double aspect = w / h;
    m_nx = std::clamp(int(std::lround(std::sqrt(cells * aspect))), 1, 512);
    m_ny = std::clamp(int(std::lround(double(cells) / m_nx)), 1, 512);
    m_u0 = lo.x;
    m_v0 = lo.y;
    m_cellW = w / m_nx;
    m_cellH = h / m_ny;
    m_invCellW = m_nx / w;
    m_invCellH = m_ny / h;
    // Built a byte a cell, then packed: classified first, then the edges
    // marked over it (an Edge cell's classification is never read).
    std::vector<Cell> grid(size_t(m_nx) * size_t(m_ny), Cell::Outside);
    classifyRows(vertices, rule, grid);
    markEdges(vertices, grid);
    pack(grid);
    measureZones(vertices);
}

void PolygonGrid::measureZones(const std::vector<Vec2>& vertices) {
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0;
    const size_t n = vertices.size();
    for (size_t k = 0; k < n; ++k) {
        const Vec2& a = vertices[k];
        nearest = std::min(nearest, originDistance(a, vertices[(k + 1) % n]));
        farthest = std::max(farthest, std::sqrt(a.x * a.x + a.y * a.y));
    }
    // The disc of radius `nearest` holds no edge, so its points share one
    // winding number; the origin's cell, if not an Edge cell, holds no edge
    // either and has the origin's. Each radius gives up one clearance, as the
    // cells keep twice it: room for the rounding of these distances (a few
    // ulps of the polygon's size, the clearance at least 2^-20 of it) and of
    // a query's own distance from the origin.
    const Cell origin = at(0, 0);
    m_originCell = origin == Cell::Edge ? Cell::Outside : origin;
    m_innerRadius = origin == Cell::Edge ? 0.0 : std::max(0.0, nearest - m_clearance);
    m_outerRadius = farthest + m_clearance;
}

void PolygonGrid::pack(const std::vector<Cell>& grid) {
    // Four cells (values 0..2) to a byte, four at a time: in the word
    // w = c0 | c1 << 8 | c2 << 16 | c3 << 24, cell c_k sits at bit 8k and
    // belongs at bit 2k.
    static_assert(kCellsPerByte == 4, "four two-bit cells to a byte");
    const size_t n = grid.size();
    m_packed.assign((n + kCellsPerByte - 1) / kCellsPerByte, 0);
    const auto* bytes = reinterpret_cast<const uint8_t*>(grid.data());
    size_t edge = 0;
    size_t k = 0;
    for (; k + 4 <= n; k += 4) {
        const uint32_t w = uint32_t(bytes[k]) | uint32_t(bytes[k + 1]) << 8 |
                           uint32_t(bytes[k + 2]) << 16 | uint32_t(bytes[k + 3]) << 24;
        m_packed[k / 4] = uint8_t((w | w >> 6 | w >> 12 | w >> 18) & 0xFFu);
        // Bit 1 of a cell is set for Edge (2) only; the multiply sums the bytes.
        edge += (((w >> 1) & 0x01010101u) * 0x01010101u) >> 24;
    }
    for (; k < n; ++k) {
        m_packed[k / kCellsPerByte] |= uint8_t(unsigned(grid[k]) << (2 * (k % kCellsPerByte)));
        edge += grid[k] == Cell::Edge;
    }
    m_edgeFraction = double(edge) / double(n);
}

void PolygonGrid::markEdges(const std::vector<Vec2>& vertices, std::vector<Cell>& cells) const {
    // A cell is marked when an edge meets it grown by twice the clearance:
    // the unmarked ones then keep the clearance with room to spare for the
    // rounding of this test and of the query's cell index.
    const double grow = 2 * m_clearance;
    // The index range of an edge's box reaches a billionth of a cell further,
    // so that rounding in (u - u0) / cell width cannot lose a cell.
    constexpr double kSlack = 1e-9;
    const auto column = [&](double u, double slack) {
        return std::clamp(int(std::floor((u - m_u0) * m_invCellW + slack)), 0, m_nx - 1);
    };
    const auto row = [&](double v, double slack) {
        return std::clamp(int(std::floor((v - m_v0) * m_invCellH + slack)), 0, m_ny - 1);
    };
    const size_t n = vertices.size();
    for (size_t k = 0; k < n; ++k) {
        const Vec2& a = vertices[k];
        const Vec2& b = vertices[(k + 1) % n];
        const int i0 = column(std::min(a.x, b.x) - grow, -kSlack);
        const int i1 = column(std::max(a.x, b.x) + grow, kSlack);
        const int j0 = row(std::min(a.y, b.y) - grow, -kSlack);
        const int j1 = row(std::max(a.y, b.y) + grow, kSlack);
        const bool oneBox = i1 - i0 <= 1 && j1 - j0 <= 1;
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                Cell& c = cells[size_t(j) * size_t(m_nx) + size_t(i)];
                if (c == Cell::Edge) continue;
                // Within a 2x2 block the cells the box touches are the ones
                // to mark (the box is conservative); a longer edge is clipped
                // against each cell so it does not mark a whole diagonal box.
                const Vec2 cellLo{m_u0 + i * m_cellW - grow, m_v0 + j * m_cellH - grow};
                const Vec2 cellHi{m_u0 + (i + 1) * m_cellW + grow, m_v0 + (j + 1) * m_cellH + grow};
                if (oneBox || segmentMeetsBox(a, b, cellLo, cellHi)) c = Cell::Edge;
            }
        }
    }
}

void PolygonGrid::classifyRows(const std::vector<Vec2>& vertices, FillRule rule,
                               std::vector<Cell>& cells) const {
    // For each row, the edges crossing the horizontal line through its cell
    // centres (half-open rule: an upward edge includes its start, excludes its
    // end); a centre's winding number is the signed count of crossings to its
    // right. No crossing lies inside a non-Edge cell (the edge would pass
    // through it), so the centre's answer is the whole cell's. Each crossing
    // becomes the column `boundary` left of which the centres see it (centre
    // x < crossing x: the centres' x grow with the column, so those columns
    // are the first ones); the cells between two boundaries share an answer
    // and are filled as a run. Gathered edge by edge: each edge visits only
    // the rows it spans.
    struct Crossing {
        int row;
        int boundary;  ///< columns [0, boundary) have their centre left of it
        int sign;      ///< +1 upward, -1 downward
    };
    std::vector<Crossing> crossings;
    crossings.reserve(2 * vertices.size());
    const auto centre = [&](int i) { return cellCentre(i, 0).x; };
    const size_t n = vertices.size();
    for (size_t k = 0; k < n; ++k) {
        const Vec2& a = vertices[k];
        const Vec2& b = vertices[(k + 1) % n];
        if (a.y == b.y) continue;
        const Vec2& lo = a.y < b.y ? a : b;
        const Vec2& hi = a.y < b.y ? b : a;
        // Rows whose centre line yc satisfies lo.y <= yc < hi.y (one row more
        // each way, re-tested exactly below).
        const int j0 = std::max(0, int(std::floor((lo.y - m_v0) * m_invCellH - 0.5)) - 1);
        const int j1 = std::min(m_ny - 1, int(std::floor((hi.y - m_v0) * m_invCellH - 0.5)) + 1);
        for (int j = j0; j <= j1; ++j) {
            const double yc = cellCentre(0, j).y;
            if ((a.y <= yc) == (b.y <= yc)) continue;
            const double x = a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
            // An estimate, then the exact comparisons settle it (NaN: none).
            const double estimate = std::floor((x - m_u0) * m_invCellW + 0.5);
            int boundary = estimate >= 0 ? (estimate <= m_nx ? int(estimate) : m_nx) : 0;
            while (boundary > 0 && !(x > centre(boundary - 1))) --boundary;
            while (boundary < m_nx && x > centre(boundary)) ++boundary;
            crossings.push_back({j, boundary, b.y > a.y ? 1 : -1});
        }
    }
    // Row by row, right to left: the cells right of every boundary are
    // outside (no crossing to their right); each boundary passed adds its
    // crossing to those of the cells left of it. Grouped by row (a counting
    // sort), then each row's crossings sorted by boundary, highest first
    // (std::sort: a comb-like outline can put thousands in one row).
    std::vector<int> rowStart(size_t(m_ny) + 1, 0);
    for (const Crossing& c : crossings) ++rowStart[size_t(c.row) + 1];
    for (int j = 0; j < m_ny; ++j) rowStart[size_t(j) + 1] += rowStart[size_t(j)];
    std::vector<Crossing> byRow(crossings.size());
    {
        std::vector<int> slot(rowStart.begin(), rowStart.end() - 1);
        for (const Crossing& c : crossings) byRow[size_t(slot[size_t(c.row)]++)] = c;
    }
    for (int j = 0; j < m_ny; ++j) {
        Crossing* const first = byRow.data() + rowStart[size_t(j)];
        Crossing* const last = byRow.data() + rowStart[size_t(j) + 1];
        std::sort(first, last,
                  [](const Crossing& p, const Crossing& q) { return p.boundary > q.boundary; });
        Cell* row = cells.data() + size_t(j) * size_t(m_nx);
        int winding = 0, count = 0;
        int right = m_nx;  // cells [right, m_nx) are filled
        const auto fill = [&](int from) {
            const bool inside = rule == FillRule::EvenOdd ? (count & 1) != 0 : winding != 0;
            std::fill(row + from, row + right, inside ? Cell::Inside : Cell::Outside);
            right = from;
        };
        for (const Crossing* c = first; c != last; ++c) {
            fill(c->boundary);
            winding += c->sign;
            ++count;
        }
        fill(0);
    }
}

double PolygonGrid::edgeFraction() const { return m_edgeFraction; }

}  // namespace raylab
