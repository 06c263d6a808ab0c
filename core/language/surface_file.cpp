#include "core/language/surface_file.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

namespace sprout {
namespace {

constexpr int kTessellation = 8;  // quads per patch side

// "CONTACT POINT X: 0 Y: 0 Z: 0" -> the three numbers after X:, Y:, Z:.
bool vectorAfter(const std::string& line, glm::vec3& out) {
    const char* keys[] = {"X:", "Y:", "Z:"};
    for (int k = 0; k < 3; ++k) {
        size_t at = line.find(keys[k]);
        if (at == std::string::npos) return false;
        std::istringstream in(line.substr(at + 2));
        if (!(in >> out[k])) return false;
    }
    return true;
}

glm::vec3 bezier(const glm::vec3 p[16], float u, float v, glm::vec3* du, glm::vec3* dv) {
    auto basis = [](float t, float b[4], float d[4]) {
        const float s = 1 - t;
        b[0] = s * s * s, b[1] = 3 * t * s * s, b[2] = 3 * t * t * s, b[3] = t * t * t;
        d[0] = -3 * s * s, d[1] = 3 * s * s - 6 * t * s, d[2] = 6 * t * s - 3 * t * t, d[3] = 3 * t * t;
    };
    float bu[4], du_[4], bv[4], dv_[4];
    basis(u, bu, du_);
    basis(v, bv, dv_);
    glm::vec3 r(0), ru(0), rv(0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const glm::vec3& c = p[i * 4 + j];
            r += bu[i] * bv[j] * c;
            ru += du_[i] * bv[j] * c;
            rv += bu[i] * dv_[j] * c;
        }
    *du = ru;
    *dv = rv;
    return r;
}

}  // namespace

std::optional<SurfaceFile> parseSurfaceFile(std::string_view text, std::string& error) {
    std::istringstream in{std::string(text)};
    std::string line;
    int number = 0;
    glm::vec3 contact(0), heading(0, 1, 0), up(0, 0, 1);
    float size = 1;
    bool sawHeader = false;
    std::vector<float> numbers;  // control points of the patch being read
    SurfaceFile out;
    auto fail = [&](const std::string& what) {
        error = "line " + std::to_string(number) + ": " + what;
        return std::nullopt;
    };
    auto addPatch = [&](const std::vector<float>& v) {
        glm::vec3 p[16];
        for (int k = 0; k < 16; ++k) p[k] = {v[size_t(k * 3)], v[size_t(k * 3 + 1)], v[size_t(k * 3 + 2)]};
        const glm::vec3 h = glm::normalize(heading), u = glm::normalize(up - glm::dot(up, h) * h);
        const glm::vec3 l = glm::cross(u, h);
        const std::uint32_t base = std::uint32_t(out.positions.size());
        for (int i = 0; i <= kTessellation; ++i)
            for (int j = 0; j <= kTessellation; ++j) {
                glm::vec3 du, dv;
                const glm::vec3 raw = bezier(p, float(i) / kTessellation, float(j) / kTessellation, &du, &dv), q = raw - contact;
                glm::vec3 n = glm::cross(du, dv);
                n = glm::length(n) > 1e-12f ? glm::normalize(n) : u;
                out.positions.push_back(glm::vec3(glm::dot(q, h), glm::dot(q, l), glm::dot(q, u)) / size);
                out.normals.push_back({glm::dot(n, h), glm::dot(n, l), glm::dot(n, u)});
                out.uvs.push_back({float(i) / kTessellation, float(j) / kTessellation});  // the patch's own (cpfg's per patch)
                out.surfaceUvs.push_back({raw.x, raw.y});  // made the surface's below
            }
        const std::uint32_t row = kTessellation + 1;
        for (std::uint32_t i = 0; i < kTessellation; ++i)
            for (std::uint32_t j = 0; j < kTessellation; ++j) {
                const std::uint32_t a = base + i * row + j, b = a + 1, c = a + row, d = c + 1;
                out.indices.insert(out.indices.end(), {a, c, d, a, d, b});
            }
        ++out.patches;
    };
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (line.find("CONTACT POINT") != std::string::npos) {
            if (!vectorAfter(line, contact)) return fail("expected 'CONTACT POINT X: x Y: y Z: z'");
            sawHeader = true;
        } else if (line.find("END POINT") != std::string::npos) {
            glm::vec3 ignored;
            if (!vectorAfter(line, ignored)) return fail("expected 'END POINT X: x Y: y Z: z'");
        } else if (line.find("HEADING") != std::string::npos) {
            if (!vectorAfter(line, heading) || !(glm::length(heading) > 0)) return fail("expected 'HEADING X: x Y: y Z: z', not zero");
        } else if (line.find("UP") == 0 || line.find(" UP ") != std::string::npos || line.rfind("UP X:", 0) == 0) {
            if (!vectorAfter(line, up)) return fail("expected 'UP X: x Y: y Z: z'");
        } else if (line.find("SIZE:") != std::string::npos) {
            std::istringstream s(line.substr(line.find("SIZE:") + 5));
            if (!(s >> size) || !(size > 0) || !std::isfinite(size)) return fail("expected 'SIZE: s' with s above 0");
        } else if (line.find("COLOR:") != std::string::npos || line.find("AL:") != std::string::npos ||
                   line.find("BL:") != std::string::npos || line.rfind("L:", 0) == 0 ||
                   line.find(" L:") != std::string::npos) {
            continue;  // colours and neighbour names: Sprout colours surfaces by the turtle's colour
        } else {
            std::istringstream s(line);
            std::vector<float> row;
            float x;
            while (s >> x) row.push_back(x);
            if (!s.eof()) {  // a word: a patch name (or the bounding box line before the header)
                if (!numbers.empty()) return fail("a patch has " + std::to_string(numbers.size() / 3) + " control points, not 16");
                continue;
            }
            for (float f : row)
                if (!std::isfinite(f)) return fail("a control point is not a finite number");
            if (!sawHeader) continue;  // the bounding box line
            numbers.insert(numbers.end(), row.begin(), row.end());
            if (numbers.size() == 48) {
                addPatch(numbers);
                numbers.clear();
            } else if (numbers.size() > 48) {
                return fail("a patch has more than 16 control points");
            }
        }
    }
    if (!numbers.empty()) return fail("the last patch has " + std::to_string(numbers.size() / 3) + " control points, not 16");
    // cpfg's texture per surface (patches.c, set_texture_coordinates): x and y over their ranges.
    std::array<float, 2> lo{0, 0}, hi{0, 0};
    for (size_t k = 0; k < out.surfaceUvs.size(); ++k)
        for (size_t c = 0; c < 2; ++c) {
            lo[c] = k ? std::min(lo[c], out.surfaceUvs[k][c]) : out.surfaceUvs[k][c];
            hi[c] = k ? std::max(hi[c], out.surfaceUvs[k][c]) : out.surfaceUvs[k][c];
        }
    for (auto& uv : out.surfaceUvs)
        for (size_t c = 0; c < 2; ++c) uv[c] = hi[c] > lo[c] ? (uv[c] - lo[c]) / (hi[c] - lo[c]) : 0.0f;
    if (out.patches == 0) {
        number = 0;
        error = "no Bezier patch in it (a cpfg surface file has a CONTACT POINT line and patches of 16 control points)";
        return std::nullopt;
    }
    return out;
}

}  // namespace sprout
