#include "core/run_program.h"

#include <fcntl.h>
#include <spawn.h>
#include <unistd.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

extern char** environ;

namespace lucent {

namespace {

std::filesystem::path thisProgram() {
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) throw Error("/proc/self/exe", "cannot find this program's directory: " + error.message());
    return exe;
}

}  // namespace

int runProgram(const std::vector<std::string>& argv, const std::filesystem::path& log, ProgramUsage* usage) {
    if (argv.empty()) throw Error("runProgram: no program");
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (!log.empty()) {
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    }
    pid_t pid = 0;
    const int started = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (started != 0) throw Error(argv[0], std::string("cannot start: ") + std::strerror(started));
    int status = 0;
    rusage used{};
    while (wait4(pid, &status, 0, &used) < 0)
        if (errno != EINTR) throw Error(argv[0], std::string("cannot wait for it: ") + std::strerror(errno));
    if (usage) {
        auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
        usage->cpuSeconds = seconds(used.ru_utime) + seconds(used.ru_stime);
        usage->peakResidentKb = used.ru_maxrss;  // Linux: kilobytes
    }
    if (WIFSIGNALED(status)) throw Error(argv[0], "killed by signal " + std::to_string(WTERMSIG(status)));
    return WEXITSTATUS(status);
}

std::filesystem::path installedDataFile(const std::string& name) {
    const std::filesystem::path file = thisProgram().parent_path().parent_path() / "share" / "lucent" / name;
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
        throw Error(file.string(), "missing (is Lucent installed whole?)");
    return file;
}

std::filesystem::path siblingProgram(const std::string& name) {
    const std::filesystem::path file = thisProgram().parent_path() / name;
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) throw Error(file.string(), "missing (is Lucent built whole?)");
    return file;
}

}  // namespace lucent
