#include "geometry/polygon_grid.h"

#include <algorithm>
#include <cmath>
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
    // Built a byte a cell, then packed.
    std::vector<Cell> grid(size_t(m_nx) * size_t(m_ny), Cell::Outside);
    markEdges(vertices, grid);
    classifyRows(vertices, rule, grid);
    m_packed.assign((grid.size() + kCellsPerByte - 1) / kCellsPerByte, 0);
    size_t edge = 0;
    for (size_t k = 0; k < grid.size(); ++k) {
        m_packed[k / kCellsPerByte] |= uint8_t(unsigned(grid[k]) << (2 * (k % kCellsPerByte)));
        edge += grid[k] == Cell::Edge;
    }
    m_edgeFraction = double(edge) / double(grid.size());
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
    // end), sorted by x; a centre's winding number is the signed count of
    // crossings to its right. No crossing lies inside a non-Edge cell (the
    // edge would pass through it), so the centre's answer is the whole cell's.
    // Gathered edge by edge: each edge visits only the rows it spans.
    std::vector<std::vector<std::pair<double, int>>> crossings(static_cast<size_t>(m_ny));  // (x, ±1)
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
            const double yc = m_v0 + (j + 0.5) * m_cellH;
            if ((a.y <= yc) == (b.y <= yc)) continue;
            const double x = a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
            crossings[size_t(j)].push_back({x, b.y > a.y ? 1 : -1});
        }
    }
    for (int j = 0; j < m_ny; ++j) {
        auto& row = crossings[size_t(j)];
        std::sort(row.begin(), row.end());
        int winding = 0, count = 0;
        size_t right = row.size();  // row[right..] lie right of the centre
        for (int i = m_nx - 1; i >= 0; --i) {
            const double xc = m_u0 + (i + 0.5) * m_cellW;
            while (right > 0 && row[right - 1].first > xc) {
                --right;
                winding += row[right].second;
                ++count;
            }
            Cell& c = cells[size_t(j) * size_t(m_nx) + size_t(i)];
            if (c == Cell::Edge) continue;
            const bool inside = rule == FillRule::EvenOdd ? (count & 1) != 0 : winding != 0;
            c = inside ? Cell::Inside : Cell::Outside;
        }
    }
}

double PolygonGrid::edgeFraction() const { return m_edgeFraction; }

}  // namespace raylab
