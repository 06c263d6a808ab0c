#pragma once
// An export started from the viewer runs on its own thread, so the window keeps drawing and
// the panel shows a progress bar; the plant's geometry is shared, not copied.
#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "core/geometry.hpp"

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

}  // namespace sprout::viewer
