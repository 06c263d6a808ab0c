#include "app/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace sprout::render {

void Camera::zoom(float k) {
    if (!(k > 0)) return;
    distance = std::clamp(distance * k, 1e-6f, 1e12f);
    orthoHeight = std::clamp(orthoHeight * k, 1e-6f, 1e12f);
}

glm::vec3 Camera::eye() const {
    float y = glm::radians(yaw), p = glm::radians(pitch);
    glm::vec3 dir(std::sin(y) * std::cos(p), std::sin(p), std::cos(y) * std::cos(p));
    return target + dir * distance;
}

glm::mat4 Camera::view() const {
    glm::vec3 up = std::fabs(pitch) > 89.0f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    const glm::vec3 from = eye();
    if (roll != 0) {  // the up vector turned about the viewing direction
        const glm::vec3 forward = glm::normalize(target - from);
        up = glm::vec3(glm::rotate(glm::mat4(1), glm::radians(roll), forward) * glm::vec4(up, 0));
    }
    return glm::lookAt(from, target, up);
}

glm::mat4 Camera::projection(float aspect, float near, float far) const {
    if (orthographic) {
        float h = orthoHeight * 0.5f, w = h * aspect;
        return glm::ortho(-w, w, -h, h, near, far);
    }
    return glm::perspective(glm::radians(fovY), aspect, near, far);
}

Camera frameBounds(const Bounds& bounds, float aspect, ViewPreset view, bool planarCurve) {
    Camera c;
    glm::vec3 size = bounds.empty ? glm::vec3(1) : bounds.size();
    c.target = bounds.empty ? glm::vec3(0) : bounds.centre();
    bool flat = size.z <= 1e-3f * std::max({size.x, size.y, 1e-6f});
    switch (view) {
        case ViewPreset::Front: break;
        case ViewPreset::Side: c.yaw = 90; break;
        case ViewPreset::Top: c.pitch = 90; break;
        case ViewPreset::Iso: c.yaw = 35; c.pitch = 25; break;
        case ViewPreset::Auto:
            if (!flat) {  // a 3D plant: a little from the side and above
                c.yaw = 30;
                c.pitch = 12;
            } else if (!planarCurve) {
                c.pitch = 6;  // a flat plant: face-on, just enough to see its ground
            }
            break;
    }
    const float margin = 1.08f;
    if (planarCurve) {
        // Face-on and orthographic: the drawing fills the frame like the book's figures.
        c.orthographic = true;
        float h = std::max(size.y, size.x / aspect);
        c.orthoHeight = std::max(h, 1e-4f) * margin;
        c.distance = std::max({size.x, size.y, size.z, 1e-3f}) * 2 + 1;
    }
    if (!c.orthographic) {
        // The nearest distance at which all eight corners of the box are inside the view
        // (exact for this direction, tighter than a bounding sphere).
        const float tanY = std::tan(glm::radians(c.fovY) / 2), tanX = tanY * aspect;
        c.distance = 1.0f;
        glm::vec3 dir = glm::normalize(c.eye() - c.target);  // towards the camera
        glm::vec3 up = std::fabs(dir.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
        glm::vec3 right = glm::normalize(glm::cross(up, dir));
        glm::vec3 camUp = glm::cross(dir, right);
        float need = 1e-3f;
        for (int i = 0; i < 8; ++i) {
            glm::vec3 corner = (bounds.empty ? glm::vec3(0) : bounds.min) +
                               glm::vec3(i & 1 ? size.x : 0, i & 2 ? size.y : 0, i & 4 ? size.z : 0) - c.target;
            float depth = glm::dot(corner, dir);  // towards the camera
            need = std::max({need, depth + std::fabs(glm::dot(corner, right)) * margin / tanX,
                             depth + std::fabs(glm::dot(corner, camUp)) * margin / tanY});
        }
        c.distance = need;
    }
    return c;
}

Camera frameView(const Bounds& bounds, float aspect, const ViewDirection& v) {
    Camera c;
    glm::vec3 d = v.eye - v.target;
    d = glm::length(d) > 0 ? glm::normalize(d) : glm::vec3(0, 0, 1);  // cpfg: the same points fall back to +Z
    c.yaw = glm::degrees(std::atan2(d.x, d.z));
    c.pitch = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
    c.roll = v.roll;
    c.orthographic = !v.perspective;
    c.fovY = std::clamp(v.fovY, 1.0f, 170.0f);
    const glm::vec3 size = bounds.empty ? glm::vec3(1) : bounds.size();
    c.target = bounds.empty ? glm::vec3(0) : bounds.centre();
    // The box's corners across the view, whichever way the roll turns the frame.
    const glm::vec3 up = std::fabs(d.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    const glm::vec3 right = glm::normalize(glm::cross(up, d)), camUp = glm::cross(d, right);
    float across = 1e-4f, depth = 0;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner = (bounds.empty ? glm::vec3(-0.5f) : bounds.min) - c.target +
                                 glm::vec3(i & 1 ? size.x : 0, i & 2 ? size.y : 0, i & 4 ? size.z : 0);
        const float r = std::fabs(glm::dot(corner, right)), u = std::fabs(glm::dot(corner, camUp));
        const float k = v.roll == 0 ? std::max(u, r / aspect) : std::max(u, r) * std::max(1.0f, 1.0f / aspect);
        across = std::max(across, k);
        depth = std::max(depth, std::fabs(glm::dot(corner, d)));
    }
    const float margin = 1.05f;
    c.orthoHeight = 2 * across * margin;
    c.distance = c.orthographic ? depth * 2 + 1 : depth + across * margin / std::tan(glm::radians(c.fovY) / 2);
    const float distance = c.distance;
    if (v.scale > 0) c.zoom(1.0f / v.scale);
    if (c.orthographic) c.distance = distance;  // closer by its height: the camera stays out of the plant
    return c;
}

Camera frameGeometry(const Geometry& g, float aspect, ViewPreset view) {
    Camera c = frameBounds(g.bounds, aspect, view, g.planarCurve);
    if (c.orthographic || g.bounds.empty) return c;
    // Sample the plant's points (at most ~40 k), each with how far the drawing reaches around
    // it: a stem's radius (a thick trunk is not cut at the frame's bottom), a sphere's.
    struct Reach {
        glm::vec3 p;
        float r;
    };
    std::vector<Reach> pts;
    const std::size_t n = g.cylinders.size() + g.surfaces.size() + g.polygons.positions.size();
    const std::size_t stride = std::max<std::size_t>(1, n / 40000);
    for (std::size_t i = 0; i < g.cylinders.size(); i += stride) {
        pts.push_back({g.cylinders[i].start, g.cylinders[i].startRadius});
        pts.push_back({g.cylinders[i].end, g.cylinders[i].endRadius});
    }
    for (std::size_t i = 0; i < g.surfaces.size(); i += stride) {
        const auto& s = g.surfaces[i];
        if (s.kind == SurfaceKind::Sphere) {
            pts.push_back({s.position, s.size});
            continue;
        }
        pts.push_back({s.position, 0});  // a blade: its base and tip
        pts.push_back({s.position + s.heading * s.size, 0});
    }
    for (std::size_t i = 0; i < g.polygons.positions.size(); i += stride)
        if (i < g.backdropFirst || i - g.backdropFirst >= g.backdropCount)  // a background scene is not framed
            pts.push_back({g.polygons.positions[i], 0});
    if (pts.empty()) return c;
    const glm::vec3 dir = glm::normalize(c.eye() - c.target);
    const glm::vec3 up = std::fabs(dir.y) > 0.99f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    const glm::vec3 right = glm::normalize(glm::cross(up, dir));
    const glm::vec3 camUp = glm::cross(dir, right);
    // Centre the target on the points' extent across the view, then find the nearest
    // distance at which every point is inside the frustum.
    float minR = 1e30f, maxR = -1e30f, minU = 1e30f, maxU = -1e30f;
    for (const auto& [p, r] : pts) {
        glm::vec3 q = p - c.target;
        minR = std::min(minR, glm::dot(q, right) - r);
        maxR = std::max(maxR, glm::dot(q, right) + r);
        minU = std::min(minU, glm::dot(q, camUp) - r);
        maxU = std::max(maxU, glm::dot(q, camUp) + r);
    }
    c.target += right * ((minR + maxR) / 2) + camUp * ((minU + maxU) / 2);
    const float margin = 1.08f;
    const float tanY = std::tan(glm::radians(c.fovY) / 2), tanX = tanY * aspect;
    float need = 1e-3f;
    for (const auto& [p, r] : pts) {
        glm::vec3 q = p - c.target;
        float depth = glm::dot(q, dir) + r;  // the near side of a stem is nearer the camera
        need = std::max({need, depth + (std::fabs(glm::dot(q, right)) + r) * margin / tanX,
                         depth + (std::fabs(glm::dot(q, camUp)) + r) * margin / tanY});
    }
    c.distance = need;
    return c;
}

}  // namespace sprout::render
