#pragma once
// Preset thumbnails, rendered by the same renderer in a child process (`sprout render`),
// one at a time in the background and cached on disk, so the window never waits for them
// and no second GL context shares this process.
#include <map>
#include <string>
#include <sys/types.h>
#include <vector>

#include "app/image.hpp"

namespace sprout::viewer {

class Thumbnails {
public:
    Thumbnails(std::string executable, std::string cacheDir);
    ~Thumbnails();
    // Collects a finished thumbnail, and starts the next missing one when none is being made
    // and `start` allows (the window holds them back while the view moves or refines: on two
    // cores a thumbnail's render would take one from the software rasteriser). The one being
    // made is paused (SIGSTOP) while `start` does not allow, and goes on when it does: a
    // render begun before a drag took the cores from the drag's frames and its plants.
    void poll(const std::vector<std::string>& names, bool start = true);
    // The one being made is paused.
    bool paused() const { return m_paused; }
    // A thumbnail is being made, or cached ones are still being read.
    bool making() const { return m_child > 0 || m_reading; }
    // The image, once made (nullptr until then).
    const Image* get(const std::string& name) const;
    // Set when the window uploaded the image to a texture.
    std::map<std::string, unsigned> textures;

    static constexpr int kWidth = 160, kHeight = 120;

private:
    std::string pathFor(const std::string& name) const;
    std::string m_exe, m_dir;
    std::map<std::string, Image> m_images;
    std::map<std::string, bool> m_failed;
    pid_t m_child = -1;
    bool m_paused = false;  // m_child stopped
    bool m_reading = false;
    std::string m_childName;
};

}  // namespace sprout::viewer
