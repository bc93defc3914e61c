#pragma once
// The subcommands of the lucent binary. Each registers its options on the CLI11
// app and returns the function that runs it.
#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <sstream>
#include <string>

namespace lucent {

using Command = std::function<void()>;

Command addPreprocessCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addTransportCommand(CLI::App& app);
Command addPresetsCommand(CLI::App& app);
Command addMethodsCommand(CLI::App& app);

// Adds every method's own options (methods/method_table.h, offeredOptions) to
// sub, each checked against its declaration; values and flags receive them by name.
void addMethodOptions(CLI::App& sub, std::map<std::string, std::string>& values,
                      std::map<std::string, CLI::Option*>& flags);
// Those of them given on the command line.
std::map<std::string, std::string> givenMethodOptions(const std::map<std::string, std::string>& values,
                                                      const std::map<std::string, CLI::Option*>& flags);

// A number in [lo, hi] and finite: CLI::Range lets NaN through, since every
// comparison with NaN is false.
inline CLI::Validator finiteRange(double lo, double hi) {
    std::ostringstream range;
    range << "[" << lo << " - " << hi << "]";
    return CLI::Validator(
        [lo, hi, text = range.str()](std::string& value) -> std::string {
            double v = 0.0;
            if (!CLI::detail::lexical_cast(value, v)) return "'" + value + "' is not a number";
            if (!std::isfinite(v)) return "'" + value + "' is not a finite number";
            if (v < lo || v > hi) return "'" + value + "' is not in " + text;
            return {};
        },
        "FLOAT in " + range.str());
}

// A whole number in [0, 2^64 - 1], refused rather than saturated when larger.
inline CLI::Validator unsigned64() {
    return CLI::Validator(
        [](std::string& value) -> std::string {
            uint64_t v = 0;
            const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), v);
            if (error != std::errc() || end != value.data() + value.size())
                return "'" + value + "' is not a whole number in [0, 18446744073709551615]";
            return {};
        },
        "UINT64");
}

// Prints "lucent: warning: ..." lines.
void printWarnings(const std::vector<std::string>& warnings);

}  // namespace lucent
