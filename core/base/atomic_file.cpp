#include "core/base/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sprout {
namespace {

std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string nameOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

bool resolveLinks(const std::string& path, std::string& resolved, std::string& error) {
    std::string p = path;
    for (int hops = 0; hops < 40; ++hops) {
        struct stat st{};
        if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
            resolved = p;
            return true;
        }
        std::vector<char> buf(size_t(st.st_size > 0 ? st.st_size : 4096) + 1);
        const ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size() - 1);
        if (n < 0) {
            error = std::string("cannot read the link: ") + std::strerror(errno);
            return false;
        }
        std::string target(buf.data(), size_t(n));
        p = target.starts_with("/") ? target : folderOf(p) + "/" + target;
    }
    error = "too many levels of symbolic links";
    return false;
}

unsigned newFileMode(const std::string& target) {
    struct stat st{};
    if (::stat(target.c_str(), &st) == 0) return st.st_mode & 07777;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

AtomicFile::~AtomicFile() { abort(); }

bool AtomicFile::open(const std::string& path, std::string& error) {
    abort();
    m_error.clear();
    m_bytes = 0;
    if (path == "-") {
        m_fd = STDOUT_FILENO;
        m_direct = m_stdout = true;
        m_target = "-";
        return true;
    }
    if (!resolveLinks(path, m_target, error)) return false;
    struct stat st{};
    const bool exists = ::stat(m_target.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) {
        error = "is a folder";
        return false;
    }
    if (exists && !S_ISREG(st.st_mode)) {
        // A FIFO, a terminal, a device: written as it is, never replaced.
        m_fd = ::open(m_target.c_str(), O_WRONLY | O_CLOEXEC);
        if (m_fd < 0) {
            error = std::strerror(errno);
            return false;
        }
        m_direct = true;
        return true;
    }
    m_temp = folderOf(m_target) + "/." + nameOf(m_target) + ".sprout-XXXXXX";
    std::vector<char> name(m_temp.begin(), m_temp.end());
    name.push_back('\0');
    m_fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (m_fd < 0) {
        error = std::strerror(errno);
        m_temp.clear();
        return false;
    }
    m_temp = name.data();
    (void)::fchmod(m_fd, mode_t(newFileMode(m_target)));
    m_direct = false;
    return true;
}

bool AtomicFile::write(const void* data, std::size_t n) {
    if (!m_error.empty()) return false;
    if (m_fd < 0) {
        m_error = "the file is not open";
        return false;
    }
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        const ssize_t w = ::write(m_fd, p, n);
        if (w < 0) {
            if (errno == EINTR) continue;
            m_error = std::strerror(errno);
            return false;
        }
        p += w;
        n -= size_t(w);
        m_bytes += std::uint64_t(w);
    }
    return true;
}

bool AtomicFile::commit(std::string& error) {
    if (m_fd < 0) {
        error = m_error.empty() ? "the file is not open" : m_error;
        return false;
    }
    if (m_direct) {
        const bool closeIt = !m_stdout;
        const int fd = m_fd;
        m_fd = -1;
        if (closeIt && ::close(fd) != 0 && m_error.empty()) m_error = std::strerror(errno);
        if (!m_error.empty()) {
            error = m_error;
            return false;
        }
        return true;
    }
    if (m_error.empty() && ::fsync(m_fd) != 0) m_error = std::strerror(errno);
    if (::close(m_fd) != 0 && m_error.empty()) m_error = std::strerror(errno);
    m_fd = -1;
    if (m_error.empty() && ::rename(m_temp.c_str(), m_target.c_str()) != 0) m_error = std::strerror(errno);
    if (!m_error.empty()) {
        error = m_error;
        ::unlink(m_temp.c_str());
        m_temp.clear();
        return false;
    }
    m_temp.clear();
    // The rename is durable once the folder is on disk too.
    const int dir = ::open(folderOf(m_target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        (void)::fsync(dir);
        ::close(dir);
    }
    return true;
}

void AtomicFile::abort() {
    if (m_fd >= 0 && !m_stdout) ::close(m_fd);
    m_fd = -1;
    if (!m_temp.empty()) ::unlink(m_temp.c_str());
    m_temp.clear();
    m_direct = m_stdout = false;
}

bool writeFileAtomically(const std::string& path, std::string_view data, std::string& error) {
    AtomicFile f;
    if (!f.open(path, error)) return false;
    if (!f.write(data.data(), data.size())) {
        error = f.error();
        return false;
    }
    return f.commit(error);
}

}  // namespace sprout
