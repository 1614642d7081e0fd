#pragma once
// The grid method of Haines' "Point in Polygon Strategies" (Graphics Gems IV,
// 1994), used as an exact filter in front of the watertight inside test of
// polygons with many vertices (geometry/polygon.h; SPD gears' 144-vertex faces
// spent ~3,300 instructions per watertight test, 55% of the scene's render).
//
// Built once, in the 2D frame of the polygon's plane: a uniform grid over its
// bounding rectangle. A cell is `Edge` when some edge passes within twice the
// clearance of it; every other cell is wholly inside or wholly outside the
// polygon under its fill rule, decided at the cell centre by a scan of the
// cell's row. A point outside the grid is outside. So a point that falls in a
// non-Edge cell lies at least `clearance` away from every edge, and its answer
// is the cell's, whatever rounding did to the point and to the vertices, as
// long as those errors stay below the clearance. Polygon::intersectT checks
// that bound per ray and otherwise (near edges, grazing rays) runs the
// watertight test, which stays the arbiter on shared edges.
//
// Two zones about the plane's origin need no cell at all (the polygon puts
// its centroid there): a disc that no edge comes near, whose points all share
// the origin's answer, and everything beyond the farthest vertex, which is
// outside. Most hits on SPD gears' faces land in one of them, and a radius
// costs no load of the grid's memory.

#include <cstdint>
#include <vector>

#include "geometry/primitives.h"
#include "geometry/vec2.h"

namespace raylab {

class PolygonGrid {
public:
    enum class Cell : uint8_t { Outside, Inside, Edge };

    /// \param vertices the polygon in 2D (closed implicitly, last -> first)
    /// \param rule its fill rule
    /// \param clearance the distance every non-Edge cell keeps from every edge (> 0)
    /// \param cells about how many cells to use (the grid's resolution)
    PolygonGrid(const std::vector<Vec2>& vertices, FillRule rule, double clearance, int cells);

    /// The cell of point (u, v): Outside beyond the grid.
    Cell at(double u, double v) const {
        const double x = (u - m_u0) * m_invCellW, y = (v - m_v0) * m_invCellH;
        // Written so that NaN lands outside the grid too.
        if (!(x >= 0 && x < m_nx && y >= 0 && y < m_ny)) return Cell::Outside;
        return cell(int(x), int(y));
    }

    /// The cell in column i, row j (0 <= i < columns(), 0 <= j < rows()).
    Cell cell(int i, int j) const {
        const size_t k = size_t(j) * size_t(m_nx) + size_t(i);
        return Cell((m_packed[k / kCellsPerByte] >> (2 * (k % kCellsPerByte))) & 3u);
    }
    /// The centre of that cell, where a non-Edge cell's state was decided.
    Vec2 cellCentre(int i, int j) const {
        return {m_u0 + (i + 0.5) * m_cellW, m_v0 + (j + 0.5) * m_cellH};
    }

    double clearance() const { return m_clearance; }

    /// Points (u, v) with u² + v² < innerRadius()² lie at least clearance() +
    /// innerRadius() - sqrt(u² + v²) from every edge, and all have
    /// originCell()'s answer (0 when the origin is an Edge cell: no zone).
    double innerRadius() const { return m_innerRadius; }
    /// Inside or Outside: the answer at the origin and in the whole inner disc.
    Cell originCell() const { return m_originCell; }
    /// Points farther than outerRadius() from the origin lie at least
    /// clearance() + (their distance - outerRadius()) beyond every vertex:
    /// outside the polygon, under either fill rule.
    double outerRadius() const { return m_outerRadius; }
    int columns() const { return m_nx; }
    int rows() const { return m_ny; }
    /// Fraction of the grid's cells that are Edge cells (for tests and tuning).
    double edgeFraction() const;

private:
    void markEdges(const std::vector<Vec2>& vertices, std::vector<Cell>& cells) const;
    void classifyRows(const std::vector<Vec2>& vertices, FillRule rule,
                      std::vector<Cell>& cells) const;
    /// Packs the cells into m_packed and counts the Edge ones.
    void pack(const std::vector<Cell>& grid);
    /// The zones about the origin (after pack: reads the origin's cell).
    void measureZones(const std::vector<Vec2>& vertices);

    double m_u0 = 0, m_v0 = 0;           ///< lower-left corner of the grid
    double m_cellW = 1, m_cellH = 1;     ///< cell size
    double m_invCellW = 1, m_invCellH = 1;
    int m_nx = 1, m_ny = 1;
    double m_clearance = 0;
    double m_innerRadius = 0, m_outerRadius = 0;
    Cell m_originCell = Cell::Outside;
    /// Two bits a cell, row-major, row 0 at m_v0. A byte a cell put SPD gears'
    /// 128 grids (9 KB each) beyond a core's L2 cache, and more than half of
    /// the lookup's time went to the load of the cell.
    static constexpr size_t kCellsPerByte = 4;
    std::vector<uint8_t> m_packed;
    double m_edgeFraction = 0;
};

}  // namespace raylab
