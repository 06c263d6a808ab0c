#pragma once
// PlantGL's Point3Grid (its regularpointgrid.h, in double precision), for L-Py models that
// grow towards attractor points (space colonisation): a regular grid of voxels over the points'
// bounds, each voxel keeping the indices of its points in the order they were added. Queries
// walk the voxels near the query (the last coordinate fastest) and each voxel's points in
// order, so they give PlantGL's indices in PlantGL's order. Disabling a point takes it out of
// its voxel; enabling puts it back at the voxel's end. Sprout's openalea.plantgl Point3Grid
// (lpy/plantgl/plantgl_grids.py) reads its arguments and calls this.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sprout {

class PointGrid {
public:
    using Vec = std::array<double, 3>;
    // `size`: each voxel's size (below 1e-5 becomes 1e-5); `lower`, `upper`: the grid's corners.
    PointGrid(std::vector<Vec> points, Vec size, Vec lower, Vec upper);

    std::size_t size() const { return m_points.size(); }
    const Vec& point(std::size_t i) const { return m_points[i]; }

    std::vector<std::uint32_t> ballQuery(const Vec& centre, double radius) const;
    // Points within `radius` of `centre` and `angle` (the cone's full opening, radians) of
    // `direction`.
    std::vector<std::uint32_t> coneQuery(const Vec& centre, const Vec& direction, double radius, double angle) const;

    bool disable(std::size_t i);  // false: it was not enabled
    bool enable(std::size_t i);   // false: it was
    bool enabled(std::size_t i) const;

private:
    using Index = std::array<std::uint64_t, 3>;
    Index indexOf(const Vec& p) const;
    std::uint64_t cellId(const Index& index) const;
    Vec centreOf(const Index& index) const;
    // The voxels of the box around `centre` reaching `radius`, the last coordinate fastest.
    template <class Visit>
    void around(const Vec& centre, double radius, Visit visit) const;
    const std::vector<std::uint32_t>* voxel(std::uint64_t id) const;

    std::vector<Vec> m_points;
    Vec m_size{}, m_lower{};
    Index m_dims{};
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_voxels;
};

}  // namespace sprout
