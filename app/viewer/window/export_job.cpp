#include "app/viewer/window/export_job.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/base/read_file.hpp"

#include "app/export/export.hpp"

extern char** environ;
#include <cstring>
#include <fcntl.h>

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

VideoJob::~VideoJob() {
    if (m_child > 0) {
        ::kill(m_child, SIGTERM);
        ::waitpid(m_child, nullptr, 0);
    }
}

double VideoJob::seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count(); }

bool VideoJob::start(const std::string& text, const std::string& kind, const std::string& path, int iterations, std::uint64_t seed,
                     int width, int height, std::string& error) {
    if (m_child > 0) {
        error = "a video is still being recorded to " + m_path;
        return false;
    }
    const auto tmp = std::filesystem::temp_directory_path();
    const std::string tag = std::to_string(::getpid());
    m_grammarFile = (tmp / ("sprout-video-" + tag + ".lsys")).string();
    m_errFile = (tmp / ("sprout-video-" + tag + ".txt")).string();
    std::ofstream(m_grammarFile, std::ios::binary) << text;
    const std::string n = std::to_string(iterations), s = std::to_string(seed),
                      size = std::to_string(width) + "x" + std::to_string(height);
    const char* argv[] = {m_exe.c_str(), "render", m_grammarFile.c_str(), "--animate", kind.c_str(), "-n", n.c_str(), "--seed",
                          s.c_str(), "--size", size.c_str(), "-o", path.c_str(), nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, m_errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    int rc = posix_spawn(&pid, m_exe.c_str(), &actions, nullptr, const_cast<char* const*>(argv), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) {
        error = "cannot start " + m_exe + ": " + std::strerror(rc);
        return false;
    }
    m_child = pid;
    m_path = path;
    m_started = std::chrono::steady_clock::now();
    return true;
}

std::string VideoJob::poll() {
    if (m_child <= 0) return {};
    int status = 0;
    pid_t r = ::waitpid(m_child, &status, WNOHANG);
    if (r == 0) return {};
    m_child = -1;
    std::string err = readFile(m_errFile).value_or("");
    std::filesystem::remove(m_grammarFile);
    std::filesystem::remove(m_errFile);
    while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
    if (r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        char buf[64];
        std::snprintf(buf, sizeof buf, " in %.1f s", seconds());
        return "recorded " + m_path + buf + (err.empty() ? "" : " (" + err.substr(err.find_last_of('\n') + 1) + ")");
    }
    return err.empty() ? "recording " + m_path + " failed" : err;
}

}  // namespace sprout::viewer
