#pragma once
// Writing a file so that what is already there is never hurt:
// - a symbolic link is followed: the file it names is replaced and the link stays a link;
// - the data goes to a temporary with a unique name beside that file (mkstemp: a file of
//   someone else's is never overwritten, and two Sprouts saving at once do not collide),
//   is flushed and fsynced, renamed over the target, and the folder is fsynced; on every
//   failure the temporary is removed and the old file is left as it was;
// - a target that exists and is not a regular file (a FIFO, a terminal, /dev/stdout in a
//   pipeline) is written directly, never renamed over;
// - "-" is standard output.
// Used by every writer: PNG pictures and video frames, exports, saved grammars.
#include <cstdio>
#include <string>
#include <string_view>

namespace sprout {

class AtomicFile {
public:
    AtomicFile() = default;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile();  // without commit(): the temporary is removed, the target untouched

    // False with `error` set when the place cannot be written.
    bool open(const std::string& path, std::string& error);
    // Writes all of `n` bytes (retrying short writes); remembers the first error.
    bool write(const void* data, std::size_t n);
    bool ok() const { return m_error.empty(); }
    const std::string& error() const { return m_error; }
    std::uint64_t bytes() const { return m_bytes; }
    // Makes the data the target's: fsync, rename, fsync of the folder. False (and the old
    // file kept) on any failure, with `error` set.
    bool commit(std::string& error);
    // Abandons the write: the temporary is removed.
    void abort();

    // What open() decided, for tests and messages.
    const std::string& target() const { return m_target; }  // the file finally written
    bool direct() const { return m_direct; }

private:
    int m_fd = -1;
    bool m_direct = false;  // written in place (not a regular file, or standard output)
    bool m_stdout = false;
    std::string m_target, m_temp;
    std::string m_error;
    std::uint64_t m_bytes = 0;
};

// The permissions a file replacing `target` gets: the old file's, or the usual ones for a new
// file (0666 less the umask). Temporaries are made 0600 and given these before the rename.
unsigned newFileMode(const std::string& target);

// The whole of `data` through an AtomicFile.
bool writeFileAtomically(const std::string& path, std::string_view data, std::string& error);

// Follows symbolic links (relative ones from their own folder) to the file they name, which
// need not exist yet. Fails on a loop.
bool resolveLinks(const std::string& path, std::string& resolved, std::string& error);

}  // namespace sprout
