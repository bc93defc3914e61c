#include "apps/run_program.h"

#include <fcntl.h>
#include <spawn.h>
#include <unistd.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

extern char** environ;

namespace lucent {

int runProgram(const std::vector<std::string>& argv, const std::filesystem::path& log) {
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
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw Error(argv[0], std::string("cannot wait for it: ") + std::strerror(errno));
    if (WIFSIGNALED(status)) throw Error(argv[0], "killed by signal " + std::to_string(WTERMSIG(status)));
    return WEXITSTATUS(status);
}

std::filesystem::path installedDataFile(const std::string& name) {
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) throw Error("/proc/self/exe", "cannot find this program's directory: " + error.message());
    const std::filesystem::path file = exe.parent_path().parent_path() / "share" / "lucent" / name;
    if (!std::filesystem::is_regular_file(file, error)) throw Error(file.string(), "missing (is Lucent installed whole?)");
    return file;
}

}  // namespace lucent
