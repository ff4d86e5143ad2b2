// SPDX-License-Identifier: Zlib
#include "IsolatedRun.h"

#include <btFracture/core/Error.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>

namespace btfracture {

namespace {

void writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

IsolatedRun runIsolated(const std::function<std::string()>& run, double memoryLimitMegabytes,
                        double cpuLimitSeconds) {
    std::fflush(stdout);
    std::fflush(stderr);
    int fds[2];
    if (pipe(fds) != 0) throw Error("isolated run: pipe() failed");
    const pid_t pid = fork();
    if (pid < 0) throw Error("isolated run: fork() failed");
    if (pid == 0) {
        close(fds[0]);
        // The first byte tells the parent what follows: 'R' the result, 'E' an error message.
        int status = 0;
        try {
            if (memoryLimitMegabytes > 0.0) {
                const rlim_t bytes = static_cast<rlim_t>(memoryLimitMegabytes * 1024.0 * 1024.0);
                const rlimit limit{bytes, bytes};
                if (setrlimit(RLIMIT_AS, &limit) != 0) throw Error("setrlimit(RLIMIT_AS) failed");
            }
            if (cpuLimitSeconds > 0.0) {
                const rlim_t seconds = static_cast<rlim_t>(std::ceil(cpuLimitSeconds));
                const rlimit limit{seconds, seconds + 10};  // SIGXCPU at the soft limit
                if (setrlimit(RLIMIT_CPU, &limit) != 0) throw Error("setrlimit(RLIMIT_CPU) failed");
            }
            writeAll(fds[1], "R" + run());
        } catch (const std::bad_alloc&) {
            writeAll(fds[1], "Eout of memory (address-space limit " +
                                 std::to_string(static_cast<long>(memoryLimitMegabytes)) + " MB)");
            status = 1;
        } catch (const std::exception& e) {
            writeAll(fds[1], std::string("E") + e.what());
            status = 1;
        }
        close(fds[1]);
        std::fflush(stdout);
        _exit(status);
    }
    close(fds[1]);
    std::string text;
    char buffer[65536];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
        text.append(buffer, static_cast<std::size_t>(n));
    close(fds[0]);
    int status = 0;
    struct rusage usage {};
    wait4(pid, &status, 0, &usage);
    IsolatedRun r;
    r.peakMegabytes = usage.ru_maxrss / 1024.0;  // ru_maxrss is in kB on Linux
    r.cpuSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                   1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
    if (!text.empty() && text[0] == 'R' && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        r.ok = true;
        r.text = text.substr(1);
    } else if (!text.empty() && text[0] == 'E') {
        r.failure = text.substr(1);
    } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
        r.failure = "over the CPU time limit of " +
                    std::to_string(static_cast<long>(std::ceil(cpuLimitSeconds))) + " s";
    } else if (WIFSIGNALED(status)) {
        r.failure = std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                    strsignal(WTERMSIG(status)) + ")";
    } else {
        r.failure = "exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    }
    return r;
}

}  // namespace btfracture
