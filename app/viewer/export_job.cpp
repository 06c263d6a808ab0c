#include "app/viewer/export_job.hpp"

#include <chrono>
#include <cstdio>

#include "app/export/export.hpp"

namespace sprout::viewer {

ExportJob::~ExportJob() {
    if (m_thread.joinable()) m_thread.join();
}

bool ExportJob::start(std::shared_ptr<const Geometry> geometry, const std::string& path, std::string& error) {
    if (m_running) {
        error = "an export to " + m_path + " is still running";
        return false;
    }
    auto format = exporter::formatFromPath(path);
    if (!format) {
        error = "cannot tell the format of " + path + ": use .glb, .obj, .ply or .svg";
        return false;
    }
    if (!geometry) {
        error = "there is no plant to export yet";
        return false;
    }
    if (m_thread.joinable()) m_thread.join();
    m_path = path;
    m_progress = 0;
    m_running = true;
    m_thread = std::thread([this, geometry, path, f = *format] {
        auto t0 = std::chrono::steady_clock::now();
        exporter::ExportOptions o;
        o.generator = "Sprout " SPROUT_VERSION;
        o.progress = [this](double p) { m_progress = p; };
        exporter::ExportStats st;
        std::string err;
        bool ok = exporter::exportGeometry(*geometry, path, f, o, st, err);
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char buf[256];
        if (ok)
            std::snprintf(buf, sizeof buf, "exported %s: %zu triangles, %.1f MB in %.1f s", path.c_str(), st.triangles,
                          double(st.bytes) / (1 << 20), secs);
        {
            std::lock_guard lock(m_mutex);
            m_message = ok ? std::string(buf) : path + ": " + err;
        }
        m_progress = 1;
        m_running = false;
    });
    return true;
}

std::string ExportJob::takeMessage() {
    if (m_running) return {};
    std::lock_guard lock(m_mutex);
    return std::exchange(m_message, {});
}

}  // namespace sprout::viewer
