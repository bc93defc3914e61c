#include "core/isolated.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>
#include <cstring>

#include "core/error.h"

namespace lucent {

std::string deathInChild(const std::function<void()>& work, double timeoutSeconds) {
    const pid_t pid = ::fork();
    if (pid < 0) throw Error(std::string("cannot fork to read a file safely: ") + std::strerror(errno));
    if (pid == 0) {
        // What the library prints as it dies (an assertion, a sanitizer report) is
        // not the user's business: the parent says in one line what happened.
        const int devNull = ::open("/dev/null", O_WRONLY);
        if (devNull >= 0) {
            ::dup2(devNull, STDOUT_FILENO);
            ::dup2(devNull, STDERR_FILENO);
        }
        try {
            work();
        } catch (...) {
        }
        ::_exit(0);
    }
    int status = 0;
    const auto start = std::chrono::steady_clock::now();
    for (auto pause = std::chrono::microseconds(200);; pause = std::min(2 * pause, std::chrono::microseconds(50000))) {
        const pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (done < 0 && errno != EINTR) throw Error(std::string("cannot wait for a child: ") + std::strerror(errno));
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeoutSeconds) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            char text[64];
            std::snprintf(text, sizeof text, "no answer after %.0f s", timeoutSeconds);
            return text;
        }
        std::this_thread::sleep_for(pause);
    }
    if (WIFSIGNALED(status))
        return "signal " + std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    if (WIFEXITED(status) && WEXITSTATUS(status) != 0) return "exit status " + std::to_string(WEXITSTATUS(status));
    return {};
}

}  // namespace lucent
