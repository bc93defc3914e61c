#pragma once
// The subcommands of the lucent binary. Each registers its options on the CLI11
// app and returns the function that runs it.
#include <CLI/CLI.hpp>

#include <functional>

namespace lucent {

using Command = std::function<void()>;

Command addPreprocessCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);

// Prints "lucent: warning: ..." lines.
void printWarnings(const std::vector<std::string>& warnings);

}  // namespace lucent
