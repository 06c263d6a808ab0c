#pragma once
// SVG: the plant projected onto its plane (planar systems) or seen from the front (3D
// plants): stems as polylines with their widths and colours, leaves and polygons filled.
#include <string>

#include "app/export/export.hpp"

namespace sprout::exporter {

bool writeSvg(const Geometry& geometry, const std::string& path, const ExportOptions& options, ExportStats& stats,
              std::string& error);

}  // namespace sprout::exporter
