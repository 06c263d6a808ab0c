#include "app/viewer/window/thumbnails.hpp"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>

#include "app/plant/presets.hpp"

extern char** environ;

namespace sprout::viewer {

Thumbnails::Thumbnails(std::string executable, std::string cacheDir) : m_exe(std::move(executable)), m_dir(std::move(cacheDir)) {
    std::error_code ec;
    std::filesystem::create_directories(m_dir, ec);
}

Thumbnails::~Thumbnails() {
    if (m_child > 0) {
        ::kill(m_child, SIGTERM);
        if (m_paused) ::kill(m_child, SIGCONT);  // a stopped process ends once it goes on
        ::waitpid(m_child, nullptr, 0);
    }
}

std::string Thumbnails::pathFor(const std::string& name) const {
    // The preset's text is part of the name, so an edited preset gets a new thumbnail.
    auto text = presetText(name);
    std::size_t h = std::hash<std::string_view>{}(text ? *text : std::string_view());
    return m_dir + "/" + name + "-" + std::to_string(h % 1000000007ull) + ".png";
}

const Image* Thumbnails::get(const std::string& name) const {
    auto it = m_images.find(name);
    return it == m_images.end() ? nullptr : &it->second;
}

void Thumbnails::poll(const std::vector<std::string>& names, bool start) {
    if (m_child > 0) {
        if (start == m_paused) {  // held back: paused; allowed again: it goes on
            m_paused = !start;
            ::kill(m_child, start ? SIGCONT : SIGSTOP);
        }
        int status = 0;
        pid_t r = ::waitpid(m_child, &status, WNOHANG);
        if (r == 0) return;  // still rendering, or paused
        m_child = -1;
        m_paused = false;
        Image img;
        std::string error;
        if (r > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0 && readPng(pathFor(m_childName), img, error))
            m_images[m_childName] = std::move(img);
        else
            m_failed[m_childName] = true;
    }
    m_reading = false;
    // Cached ones are read a few milliseconds' worth a frame: all 80 in the first frame took 22 ms.
    const auto start0 = std::chrono::steady_clock::now();
    for (const auto& name : names) {
        if (m_images.count(name) || m_failed.count(name)) continue;
        if (std::chrono::steady_clock::now() - start0 > std::chrono::milliseconds(2)) {
            m_reading = true;  // more next frame
            return;
        }
        const std::string path = pathFor(name);
        Image img;
        std::string error;
        if (std::filesystem::exists(path) && readPng(path, img, error)) {  // cached
            m_images[name] = std::move(img);
            continue;
        }
        if (!start) return;
        const std::string size = std::to_string(kWidth) + "x" + std::to_string(kHeight);
        std::vector<std::string> args = {m_exe, "render", name, "-o", path, "--size", size};
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        pid_t pid = -1;
        if (posix_spawn(&pid, m_exe.c_str(), nullptr, nullptr, argv.data(), environ) == 0) {
            m_child = pid;
            m_childName = name;
        } else {
            m_failed[name] = true;
        }
        return;  // one at a time: leave the other core to the worker
    }
}

}  // namespace sprout::viewer
