/* A full disk, simulated: loaded with LD_PRELOAD and SPROUT_FAIL_WRITES=1, write() fails
   with ENOSPC for Sprout's temporary files (".NAME.sprout-XXXXXX") after their first
   SPROUT_FAIL_AFTER bytes (default 0), and works for everything else (standard output and
   error, the old files). Tests only: never installed. */
#define _GNU_SOURCE
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/syscall.h>
#include <unistd.h>

static long written[1024];

/* The system call itself: no dlsym, which under AddressSanitizer may not be ready when the
   first write comes (it returned null there, and the process crashed calling it). */
static ssize_t real_write(int fd, const void* buf, size_t n) { return (ssize_t)syscall(SYS_write, fd, buf, n); }

ssize_t write(int fd, const void* buf, size_t n) {
    const char* on = getenv("SPROUT_FAIL_WRITES");
    if (on && *on == '1' && fd > 2 && fd < 1024) {
        char link[64], path[4096];
        snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
        ssize_t len = readlink(link, path, sizeof path - 1);
        if (len > 0) {
            path[len] = 0;
            if (strstr(path, ".sprout-")) {
                const char* after = getenv("SPROUT_FAIL_AFTER");
                long limit = after ? atol(after) : 0;
                if (written[fd] >= limit) {
                    errno = ENOSPC;
                    return -1;
                }
                if ((long)n > limit - written[fd]) n = (size_t)(limit - written[fd]);
                ssize_t w = real_write(fd, buf, n);
                if (w > 0) written[fd] += w;
                return w;
            }
        }
    }
    return real_write(fd, buf, n);
}
