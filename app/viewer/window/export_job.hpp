#pragma once
// An export started from the viewer runs on its own thread, so the window keeps drawing and
// the panel shows a progress bar; the plant's geometry is shared, not copied.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "core/turtle/geometry.hpp"

namespace sprout::viewer {

class ExportJob {
public:
    ~ExportJob();
    // False with a message when an export is still running or the format is unknown.
    bool start(std::shared_ptr<const Geometry> geometry, const std::string& path, std::string& error);
    bool running() const { return m_running; }
    double progress() const { return m_progress; }
    const std::string& path() const { return m_path; }
    // The finished export's message, once; empty while running or after it was taken.
    std::string takeMessage();

private:
    std::thread m_thread;
    std::atomic<bool> m_running{false};
    std::atomic<double> m_progress{0};
    std::mutex m_mutex;
    std::string m_message, m_path;
};

// A growth or turntable video recorded by a child `sprout render --animate`, so the window
// keeps running while it renders (the grammar goes through a temporary file).
class VideoJob {
public:
    explicit VideoJob(std::string executable) : m_exe(std::move(executable)) {}
    ~VideoJob();
    bool start(const std::string& grammarText, const std::string& kind, const std::string& path, int iterations,
               std::uint64_t seed, int width, int height, std::string& error);
    bool running() const { return m_child > 0; }
    const std::string& path() const { return m_path; }
    double seconds() const;
    // Checks the child; returns its message once it has ended, empty while it runs.
    std::string poll();

private:
    std::string m_exe, m_path, m_grammarFile, m_errFile;
    int m_child = -1;
    std::chrono::steady_clock::time_point m_started;
};

}  // namespace sprout::viewer
