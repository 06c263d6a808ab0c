#pragma once
// PlantGL's ZBufferEngine as its light module uses it (algo/projection/zbufferengine.cpp,
// projectioncamera.cpp; algo/raycasting/ray.cpp), in double precision where PlantGL computes
// in double and in float where it does: an orthographic camera set by lookAt, an id buffer and
// a depth buffer. An orthographic camera in PlantGL intersects rays with each triangle (its
// "ray intersection" method): one ray per pixel, from the pixel's corner (x, y) (PlantGL
// truncates the pixel's centre to its integer coordinates), along the camera's axis; the depth
// kept is the intersection's distance to the camera's origin. A triangle whose raster bounds
// fall on one pixel draws that pixel whatever the ray. Segments (polylines) and points are
// drawn as PlantGL draws them (Bresenham, the raster depth). No face culling, no colours, one
// thread (PlantGL's threads change only which of two fragments of equal depth wins).
// Sprout's openalea.plantgl ZBufferEngine (lpy/plantgl/plantgl_light.py) feeds it the shapes'
// meshes (lpy/plantgl/meshes.cpp) through bind_light.cpp.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace sprout {

class ZBuffer {
public:
    using Vec = std::array<double, 3>;
    static constexpr std::uint32_t kNoId = 0xFFFFFFFFu;  // PlantGL's Shape::NOID

    ZBuffer(int width, int height, std::uint32_t defaultId = kNoId);

    int width() const { return m_width; }
    int height() const { return m_height; }

    void setOrthographicCamera(double left, double right, double bottom, double top, double nearZ, double farZ);
    void lookAt(const Vec& eye, const Vec& centre, const Vec& up);

    // World coordinates.
    void triangle(const Vec& a, const Vec& b, const Vec& c, std::uint32_t id);
    void segment(const Vec& a, const Vec& b, int width, std::uint32_t id);
    void point(const Vec& a, int width, std::uint32_t id);

    // The camera's raster coordinates of a world point (x, y in pixels, z the depth along the
    // axis).
    Vec worldToRaster(const Vec& p) const;

    // The pixels of each id (not the default one), in the order the ids are first met going
    // through the columns (x) and each column's rows (y), as PlantGL's idhistogram counts.
    std::vector<std::pair<std::uint32_t, double>> idHistogram() const;
    std::uint32_t idAt(int x, int y) const { return m_ids[index(x, y)]; }
    double depthAt(int x, int y) const { return m_depth[index(x, y)]; }

private:
    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(m_width) + std::size_t(x); }
    Vec toCamera(const Vec& p) const;
    Vec cameraToRaster(const Vec& c) const;
    bool inZRange(double zmin, double zmax) const { return !(zmax < m_near || zmin > m_far); }
    bool inZRange(double z) const;
    void render(long x, long y, double z, std::uint32_t id);
    void renderRun(int dim, const Vec& from, const Vec& to, int width, std::uint32_t id);

    int m_width, m_height;
    std::uint32_t m_default;
    std::vector<double> m_depth;
    std::vector<std::uint32_t> m_ids;
    double m_left = -1, m_right = 1, m_bottom = -1, m_top = 1, m_near = 0, m_far = 1;
    double m_xscale = 1, m_xconstant = 0, m_yscale = 1, m_yconstant = 0;
    Vec m_eye{0, 0, 0}, m_side{0, 1, 0}, m_up{0, 0, 1}, m_forward{1, 0, 0};
};

}  // namespace sprout
