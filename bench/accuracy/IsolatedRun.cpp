// SPDX-License-Identifier: Zlib
#include "IsolatedRun.h"

#include <btFracture/core/Error.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <exception>
#include <string>

namespace accuracy {

RunResult runIsolated(const std::function<RunResult()>& run, const std::string& caseName,
                      const std::string& method) {
    std::fflush(stdout);
    std::fflush(stderr);
    int fds[2];
    if (pipe(fds) != 0) throw btfracture::Error("accuracy: pipe() failed");
    const pid_t pid = fork();
    if (pid < 0) throw btfracture::Error("accuracy: fork() failed");
    if (pid == 0) {
        close(fds[0]);
        int status = 0;
        try {
            const std::string text = serialize(run());
            std::size_t done = 0;
            while (done < text.size()) {
                const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
                if (n <= 0) break;
                done += static_cast<std::size_t>(n);
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "accuracy: %s / %s failed: %s\n", caseName.c_str(), method.c_str(),
                         e.what());
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
    RunResult r;
    try {
        r = deserialize(text);
    } catch (const btfracture::Error&) {
        r.caseName = caseName;
        r.method = method;
        r.note = "run failed (exit status " + std::to_string(status) + ")";
    }
    r.peakMegabytes = usage.ru_maxrss / 1024.0;  // ru_maxrss is in kB on Linux
    return r;
}

}  // namespace accuracy
