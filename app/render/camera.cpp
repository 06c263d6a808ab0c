#include "app/render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace sprout::render {

glm::vec3 Camera::eye() const {
    float y = glm::radians(yaw), p = glm::radians(pitch);
    glm::vec3 dir(std::sin(y) * std::cos(p), std::sin(p), std::cos(y) * std::cos(p));
    return target + dir * distance;
}

glm::mat4 Camera::view() const {
    glm::vec3 up = std::fabs(pitch) > 89.0f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    return glm::lookAt(eye(), target, up);
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
            }
            break;
    }
    const float margin = 1.12f;
    if (planarCurve || (flat && view == ViewPreset::Auto)) {
        // Face-on and orthographic: the drawing fills the frame like the book's figures.
        c.orthographic = true;
        float h = std::max(size.y, size.x / aspect);
        c.orthoHeight = std::max(h, 1e-4f) * margin;
        c.distance = std::max({size.x, size.y, size.z, 1e-3f}) * 2 + 1;
        if (!planarCurve) {  // a flat plant: keep perspective, it is still drawn in 3D
            c.orthographic = false;
        }
    }
    if (!c.orthographic) {
        // Distance at which the bounding box, seen from this direction, fits the view.
        float radius = 0.5f * glm::length(size);
        float fov = glm::radians(c.fovY);
        float fovX = 2 * std::atan(std::tan(fov / 2) * aspect);
        float fit = std::min(fov, fovX);
        if (flat && view == ViewPreset::Auto) {
            // Face-on: fit the rectangle, not the sphere, so flat plants fill the frame.
            float dh = 0.5f * size.y / std::tan(fov / 2), dw = 0.5f * size.x / std::tan(fovX / 2);
            c.distance = std::max(dh, dw) * margin + 1e-3f;
        } else {
            c.distance = radius / std::sin(fit / 2) * 1.02f + 1e-3f;
        }
    }
    return c;
}

}  // namespace sprout::render
