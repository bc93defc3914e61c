#pragma once
// Runs a helper program without a shell: an argument vector, so no character of
// a path or an option can become a command.
#include <filesystem>
#include <string>
#include <vector>

namespace lucent {

// What a finished program used (wait4's rusage): processor time and peak memory.
struct ProgramUsage {
    double cpuSeconds = 0.0;  // user and system time
    // Never below the caller's own resident set at the start: the child runs in
    // the caller's memory until its exec, and Linux keeps the peak across it.
    long peakResidentKb = 0;
};

// Runs argv[0] (looked up on PATH) with argv, waits, and returns its exit code;
// throws Error when it cannot be started or dies by a signal. With a log, the
// program's standard output and error go to that file (created or truncated).
// With usage, what the program used is stored there.
int runProgram(const std::vector<std::string>& argv, const std::filesystem::path& log = {},
               ProgramUsage* usage = nullptr);

// A file Lucent installs beside its binary: <directory of this executable>/../share/lucent/name
// (the build tree has the same layout). Throws Error naming the path if it is not there.
std::filesystem::path installedDataFile(const std::string& name);

// Another program built beside this one: <directory of this executable>/name.
// Throws Error naming the path if it is not there.
std::filesystem::path siblingProgram(const std::string& name);

}  // namespace lucent
