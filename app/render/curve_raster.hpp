#pragma once
// Big planar curves drawn at the cost of their picture: a curve of millions of segments
// covers at most the pixels of the image, so instead of a ribbon per segment (two triangles
// each: 9.8 M segments took 5.6 s and 1.7 GB on software GL) its segments are rasterised on
// the CPU into a coverage image, one byte per pixel, which the renderer blends in as ink.
// Consecutive segments shorter than half a pixel are merged first (the picture cannot show
// them apart).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/turtle/geometry.hpp"

namespace sprout::render {

// Coverage (0..255) of the segments (x and y; a planar curve lies in z = 0) drawn `lineWidth`
// pixels wide, each extended by half a width at both ends as the ribbons are, in an
// imageWidth x imageHeight image whose first row is the bottom one (OpenGL's). Antialiased
// by the distance to the segment.
void rasterizeCurve(const CylinderInstance* segments, std::size_t count, const glm::mat4& viewProj, int imageWidth,
                    int imageHeight, float lineWidth, std::vector<std::uint8_t>& coverage);

}  // namespace sprout::render
