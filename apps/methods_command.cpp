// `lucent methods`: the reference of every method and its options, printed
// from the declarations in the method table (docs/methods.md is its output, and
// a test keeps the two equal).
#include <cctype>
#include <cstdio>

#include "apps/commands.h"
#include "methods/method_table.h"

namespace lucent {
namespace {

std::string markdownCell(std::string text) {
    for (size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
    return text;
}

void printMethod(const MethodEntry& m) {
    std::string summary = m.summary;
    if (!summary.empty()) summary[0] = char(std::toupper(static_cast<unsigned char>(summary[0])));
    std::printf("\n## %s\n\n%s.", m.name.c_str(), summary.c_str());
    if (m.needsSamples) std::printf(" Reads the objects' sample files: run `lucent preprocess` first.");
    if (m.interactive) std::printf(" Fast enough for the viewer.");
    std::printf("\n\n");
    if (m.options.empty()) {
        std::printf("No options of its own.\n");
        return;
    }
    std::printf("| option | takes | default | what it does |\n|---|---|---|---|\n");
    for (const OptionSpec& o : m.options)
        std::printf("| `--%s` | %s | %s | %s |\n", o.name.c_str(), markdownCell(o.domain()).c_str(),
                    o.defaultValue.c_str(), markdownCell(o.help).c_str());
}

}  // namespace

Command addMethodsCommand(CLI::App& app) {
    app.add_subcommand("methods", "Print every rendering method and its options (Markdown: docs/methods.md)");
    return [] {
        std::printf(
            "# Rendering methods\n\n"
            "`lucent render --method NAME` runs one of these; `--method auto` picks one for the scene and says why. "
            "Every method also takes the shared options of `lucent render`: `--width`, `--height`, `--threads`, "
            "`--seed`, `--no-surface` and `--exposure`. An option a method does not declare is an error, unless auto "
            "chose the method (then a warning says it is left out).\n\n"
            "This page is the output of `lucent methods` in a build with OpenCL; a test keeps the two equal.\n");
        for (const MethodEntry& m : methodTable()) printMethod(m);
    };
}

}  // namespace lucent
