// PlantGL's z-buffer for its light module (zbuffer.hpp says what of it, and from where).
#include "lpy/plantgl/zbuffer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace sprout {
namespace {

using Vec = ZBuffer::Vec;
constexpr double kEpsilon = 1e-5;     // PlantGL's GEOM_EPSILON
constexpr double kTolerance = 1e-10;  // GEOM_TOLERANCE: Vector3's ==

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
Vec normed(const Vec& a) {
    const double n = norm(a);
    return n > 0 ? Vec{a[0] / n, a[1] / n, a[2] / n} : a;
}

// PlantGL's Ray::intersect with a triangle (algo/raycasting/ray.cpp), its floats kept: 1 where
// the ray meets it.
int rayTriangle(const Vec& origin, const Vec& direction, const Vec& p1, const Vec& p2, const Vec& p3, Vec& hit) {
    const Vec u = sub(p2, p1), v = sub(p3, p1), n = cross(u, v);
    if (std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])}) < kTolerance) return -1;  // degenerate
    const Vec w0 = sub(origin, p1);
    const float a = float(dot(n, w0));
    const float b = float(dot(n, direction));
    if (std::fabs(b) < kEpsilon) return a == 0 ? 2 : 0;  // parallel to the triangle's plane
    const float r = -a / b;
    if (r < 0.0f) return 0;
    hit = {origin[0] + direction[0] * double(r), origin[1] + direction[1] * double(r), origin[2] + direction[2] * double(r)};
    const float uu = float(dot(u, u)), uv = float(dot(u, v)), vv = float(dot(v, v));
    const Vec w = sub(hit, p1);
    const float wu = float(dot(w, u)), wv = float(dot(w, v));
    const float d = uv * uv - uu * vv;
    const float s = (uv * wv - vv * wu) / d;
    if (s < 0.0f || s > 1.0f) return 0;
    const float t = (uv * wu - uu * wv) / d;
    if (t < 0.0f || (s + t) > 1.0f) return 0;
    return 1;
}

// C++'s conversion of a double to an unsigned 16-bit pixel coordinate, as PlantGL's
// isValidPixel(uint16_t, uint16_t) receives it (below 0 or past 65535: out of the image).
bool validPixel(double x, double y, int width, int height) {
    if (!(x >= 0 && y >= 0) || x >= 65536 || y >= 65536) return false;
    return long(x) < width && long(y) < height;
}

}  // namespace

ZBuffer::ZBuffer(int width, int height, std::uint32_t defaultId)
    : m_width(std::max(0, width)), m_height(std::max(0, height)), m_default(defaultId),
      m_depth(std::size_t(m_width) * std::size_t(m_height), std::numeric_limits<double>::max()),
      m_ids(std::size_t(m_width) * std::size_t(m_height), defaultId) {
    m_side = {1, 0, 0}, m_up = {0, 1, 0}, m_forward = {0, 0, 1};
}

void ZBuffer::setOrthographicCamera(double left, double right, double bottom, double top, double nearZ, double farZ) {
    m_left = left, m_right = right, m_bottom = bottom, m_top = top, m_near = nearZ, m_far = farZ;
    m_xscale = 2. / (right - left);
    m_xconstant = (right + left) / (right - left);
    m_yscale = 2. / (top - bottom);
    m_yconstant = (top + bottom) / (top - bottom);
}

// ProjectionCamera::lookAt: forward from the centre to the eye, side = up x forward.
void ZBuffer::lookAt(const Vec& eye, const Vec& centre, const Vec& up) {
    const Vec forward = normed(sub(eye, centre));
    const Vec side = normed(cross(up, forward));
    m_up = normed(cross(forward, side));
    m_side = side, m_forward = forward, m_eye = eye;
}

ZBuffer::Vec ZBuffer::toCamera(const Vec& p) const {
    const Vec d = sub(p, m_eye);
    return {dot(m_side, d), dot(m_up, d), dot(m_forward, d)};
}

// cameraToNDC (orthographic: screen2NDC), then NDCtoRasterSpace.
ZBuffer::Vec ZBuffer::cameraToRaster(const Vec& c) const {
    const double xn = m_xscale * c[0] - m_xconstant, yn = m_yscale * c[1] - m_yconstant;
    return {((xn + 1) / 2.) * m_width, ((1 - yn) / 2.) * m_height, -c[2]};
}

ZBuffer::Vec ZBuffer::worldToRaster(const Vec& p) const { return cameraToRaster(toCamera(p)); }

bool ZBuffer::inZRange(double z) const { return (z - m_near) >= -kEpsilon && (z - m_far) <= kEpsilon; }

// renderRaster / _tryRenderRaster: kept where nearer by more than GEOM_EPSILON.
void ZBuffer::render(long x, long y, double z, std::uint32_t id) {
    if (x < 0 || y < 0 || x >= m_width || y >= m_height) return;
    const std::size_t k = index(int(x), int(y));
    const double current = m_depth[k];
    if (z < current && (current - z) > kEpsilon) {
        m_depth[k] = z;
        m_ids[k] = id;
    }
}

// renderShadedTriangle and rasterize, for an orthographic camera (PlantGL's ray intersection).
void ZBuffer::triangle(const Vec& a, const Vec& b, const Vec& c, std::uint32_t id) {
    const Vec ca = toCamera(a), cb = toCamera(b), cc = toCamera(c);
    Vec ra = cameraToRaster(ca), rb = cameraToRaster(cb), rc = cameraToRaster(cc);
    for (Vec* r : {&ra, &rb, &rc}) (*r)[0] = std::round((*r)[0]), (*r)[1] = std::round((*r)[1]);
    const double xmin = std::min({ra[0], rb[0], rc[0]}), xmax = std::max({ra[0], rb[0], rc[0]});
    const double ymin = std::min({ra[1], rb[1], rc[1]}), ymax = std::max({ra[1], rb[1], rc[1]});
    const double zmin = std::min({ra[2], rb[2], rc[2]}), zmax = std::max({ra[2], rb[2], rc[2]});
    if (xmin >= m_width || xmax < 0 || ymin >= m_height || ymax < 0 || !inZRange(zmin, zmax)) return;
    // PlantGL widens these bounds to the raster triangle's circumsphere where it spans more
    // than a pixel each way; a ray can only meet the triangle within the rounded bounds.
    const long x0 = std::max(0L, long(std::floor(xmin))), x1 = std::min(long(m_width) - 1, long(std::ceil(xmax)));
    const long y0 = std::max(0L, long(std::floor(ymin))), y1 = std::min(long(m_height) - 1, long(std::ceil(ymax)));
    const bool widened = (std::floor(xmax) - std::floor(xmin) > 1) && (std::floor(ymax) - std::floor(ymin) > 1);
    if (!widened && x0 == x1 && y0 == y1) {
        if (validPixel(double(x0), double(y0), m_width, m_height)) render(x0, y0, (ra[2] + rb[2] + rc[2]) / 3, id);
        return;
    }
    const Vec direction{0, 0, -1};
    for (long y = y0; y <= y1; ++y)
        for (long x = x0; x <= x1; ++x) {
            // rasterToCameraRay(x, y): the pixel's corner, from z = 0 towards -z.
            const double xn = 2. * double(x) / m_width - 1, yn = 1 - 2. * double(y) / m_height;
            const Vec origin{(xn + m_xconstant) / m_xscale, (yn + m_yconstant) / m_yscale, -0.0};
            Vec hit;
            if (rayTriangle(origin, direction, ca, cb, cc, hit) == 1) render(x, y, norm(hit), id);
        }
}

// renderPoint: the square of `width` pixels at the point's raster position.
void ZBuffer::point(const Vec& a, int width, std::uint32_t id) {
    const Vec r = worldToRaster(a);
    if (!validPixel(r[0], r[1], m_width, m_height) || !inZRange(r[2])) return;
    const long half = long(width / 2.);
    const long x0 = std::max(0L, long(r[0]) - half), x1 = std::min(long(m_width) - 1, long(r[0]) + half);
    const long y0 = std::max(0L, long(r[1]) - half), y1 = std::min(long(m_height) - 1, long(r[1]) + half);
    for (long y = y0; y <= y1; ++y)
        for (long x = x0; x <= x1; ++x) render(x, y, r[2], id);
}

// renderSegment: both ends as points, then Bresenham along the longer raster axis.
void ZBuffer::segment(const Vec& a, const Vec& b, int width, std::uint32_t id) {
    point(a, width, id);
    point(b, width, id);
    const Vec ra = worldToRaster(a), rb = worldToRaster(b);
    const int dim = std::fabs(rb[1] - ra[1]) < std::fabs(rb[0] - ra[0]) ? 0 : 1;
    if (ra[size_t(dim)] > rb[size_t(dim)])
        renderRun(dim, rb, ra, width, id);
    else
        renderRun(dim, ra, rb, width, id);
}

// _renderSegment.
void ZBuffer::renderRun(int dim, const Vec& from, const Vec& to, int width, std::uint32_t id) {
    const size_t d = size_t(dim), o = size_t((dim + 1) % 2);
    Vec delta = sub(to, from);
    const double dz = delta[2] / delta[d];
    const double dims[2] = {double(m_width), double(m_height)};
    double step = 1;
    if (delta[o] < 0) step = -1, delta[o] = -delta[o];
    double decision = 2 * delta[o] - delta[d];
    Vec c = from;
    const long half = long(width / 2.);
    for (long guard = 0; c[d] < to[d] + 1 && guard < 1L << 20; ++guard) {
        if (0 <= c[d] && c[d] < dims[d] && 0 <= c[o] && c[o] < dims[o]) {
            const long w0 = std::max(0L, long(c[o]) - half), w1 = std::min(long(dims[o]) - 1, long(c[o] + half));
            Vec ci = c;
            for (long k = w0; k <= w1; ++k) {
                ci[o] = double(k);
                if (validPixel(ci[0], ci[1], m_width, m_height) && !std::isnan(ci[2])) render(long(ci[0]), long(ci[1]), ci[2], id);
            }
        }
        if (decision > 0) {
            c[o] += step;
            decision -= 2 * delta[d];
        }
        decision += 2 * delta[o];
        c[2] += dz;
        c[d] += 1;
    }
}

std::vector<std::pair<std::uint32_t, double>> ZBuffer::idHistogram() const {
    std::vector<std::pair<std::uint32_t, double>> out;
    std::unordered_map<std::uint32_t, std::size_t> at;
    for (int x = 0; x < m_width; ++x)
        for (int y = 0; y < m_height; ++y) {
            const std::uint32_t id = m_ids[index(x, y)];
            if (id == m_default) continue;
            const auto [it, fresh] = at.emplace(id, out.size());
            if (fresh)
                out.emplace_back(id, 1.0);
            else
                out[it->second].second += 1.0;
        }
    return out;
}

}  // namespace sprout
