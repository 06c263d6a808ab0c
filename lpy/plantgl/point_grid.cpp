#include "lpy/plantgl/point_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sprout {
namespace {

// C++'s size_t(x) of a double as PlantGL's x86-64 build computes it: truncated, a negative
// one wrapped around.
std::uint64_t sizeT(double x) {
    if (!(std::fabs(x) < 9.2e18)) return 0;
    return std::uint64_t(std::int64_t(x));
}

double norm(const PointGrid::Vec& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

PointGrid::Vec minus(const PointGrid::Vec& a, const PointGrid::Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

double dot(const PointGrid::Vec& a, const PointGrid::Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// v / |v| (v itself when it is 0), and |v|.
PointGrid::Vec unit(const PointGrid::Vec& v, double& length) {
    length = norm(v);
    if (!(length > 0)) return v;
    return {v[0] / length, v[1] / length, v[2] / length};
}

}  // namespace

PointGrid::PointGrid(std::vector<Vec> points, Vec size, Vec lower, Vec upper) : m_points(std::move(points)), m_lower(lower) {
    for (int k = 0; k < 3; ++k) {
        m_size[size_t(k)] = size[size_t(k)] > 1e-5 ? size[size_t(k)] : 1e-5;
        m_dims[size_t(k)] = sizeT((upper[size_t(k)] - lower[size_t(k)]) / m_size[size_t(k)]) + 1;
    }
    for (std::uint32_t i = 0; i < m_points.size(); ++i) m_voxels[cellId(indexOf(m_points[i]))].push_back(i);
}

PointGrid::Index PointGrid::indexOf(const Vec& p) const {
    Index out;
    for (size_t k = 0; k < 3; ++k) out[k] = sizeT((p[k] - m_lower[k]) / m_size[k]);
    return out;
}

std::uint64_t PointGrid::cellId(const Index& index) const { return index[2] + m_dims[2] * (index[1] + m_dims[1] * index[0]); }

PointGrid::Vec PointGrid::centreOf(const Index& index) const {
    Vec out;
    for (size_t k = 0; k < 3; ++k) out[k] = m_lower[k] + (double(index[k]) + 0.5) * m_size[k];
    return out;
}

template <class Visit>
void PointGrid::around(const Vec& centre, double radius, Visit visit) const {
    const Index c = indexOf(centre);
    Index lo, hi;
    for (size_t k = 0; k < 3; ++k) {
        const std::uint64_t r = sizeT(1 + radius / m_size[k]);
        lo[k] = c[k] < r ? 0 : c[k] - r;
        hi[k] = std::min(m_dims[k] - 1, c[k] + r);
        if (lo[k] > hi[k]) return;
    }
    for (std::uint64_t i = lo[0]; i <= hi[0]; ++i)
        for (std::uint64_t j = lo[1]; j <= hi[1]; ++j)
            for (std::uint64_t k = lo[2]; k <= hi[2]; ++k) {
                const Index index{i, j, k};
                const std::vector<std::uint32_t>* pts = voxel(cellId(index));
                if (pts && !pts->empty()) visit(*pts, index);
            }
}

const std::vector<std::uint32_t>* PointGrid::voxel(std::uint64_t id) const {
    auto it = m_voxels.find(id);
    return it == m_voxels.end() ? nullptr : &it->second;
}

std::vector<std::uint32_t> PointGrid::ballQuery(const Vec& centre, double radius) const {
    const double reach = radius + norm(m_size);
    std::vector<std::uint32_t> out;
    around(centre, radius, [&](const std::vector<std::uint32_t>& pts, const Index& index) {
        if (!(norm(minus(centreOf(index), centre)) < reach)) return;
        for (std::uint32_t i : pts)
            if (!(norm(minus(m_points[i], centre)) > radius)) out.push_back(i);
    });
    return out;
}

std::vector<std::uint32_t> PointGrid::coneQuery(const Vec& centre, const Vec& direction, double radius, double angle) const {
    double n = 0;
    const Vec d = unit(direction, n);
    const double reach = radius + norm(m_size);
    const double cosHalf = std::cos(angle / 2), cosLarge = std::cos(std::min(angle / 2 + M_PI / 4, M_PI));
    std::vector<std::uint32_t> out;
    around(centre, radius, [&](const std::vector<std::uint32_t>& pts, const Index& index) {
        double dist = 0;
        const Vec u = unit(minus(centreOf(index), centre), dist);
        if (!(dist < reach)) return;
        const double a = dot(u, d);
        bool inside = a > cosHalf;
        if (!inside && a > cosLarge) {
            // The voxel's corners, in PlantGL's order: each coordinate in turn set to its upper side.
            Vec lo, hi;
            for (size_t k = 0; k < 3; ++k)
                lo[k] = m_lower[k] + double(index[k]) * m_size[k], hi[k] = m_lower[k] + double(index[k] + 1) * m_size[k];
            std::vector<Vec> corners{lo};
            for (size_t k = 0; k < 3 && !inside; ++k) {
                const size_t count = corners.size();
                for (size_t q = 0; q < count; ++q) {
                    Vec c = corners[q];
                    c[k] = hi[k];
                    corners.push_back(c);
                }
            }
            for (const Vec& q : corners) {
                double m = 0;
                if (dot(unit(minus(q, centre), m), d) > cosHalf) {
                    inside = true;
                    break;
                }
            }
        }
        if (!inside) return;
        for (std::uint32_t i : pts) {
            double m = 0;
            const Vec w = unit(minus(m_points[i], centre), m);
            if (m <= radius + 1e-5 && dot(w, d) > cosHalf - 1e-5) out.push_back(i);
        }
    });
    return out;
}

bool PointGrid::disable(std::size_t i) {
    if (i >= m_points.size()) return false;
    auto it = m_voxels.find(cellId(indexOf(m_points[i])));
    if (it == m_voxels.end()) return false;
    auto at = std::find(it->second.begin(), it->second.end(), std::uint32_t(i));
    if (at == it->second.end()) return false;
    it->second.erase(at);
    return true;
}

bool PointGrid::enable(std::size_t i) {
    if (i >= m_points.size()) return false;
    auto& pts = m_voxels[cellId(indexOf(m_points[i]))];
    if (std::find(pts.begin(), pts.end(), std::uint32_t(i)) != pts.end()) return false;
    pts.push_back(std::uint32_t(i));
    return true;
}

bool PointGrid::enabled(std::size_t i) const {
    if (i >= m_points.size()) return false;
    const std::vector<std::uint32_t>* pts = voxel(cellId(indexOf(m_points[i])));
    return pts && std::find(pts->begin(), pts->end(), std::uint32_t(i)) != pts->end();
}

}  // namespace sprout
