#pragma once
// What a benchmark prints, kept as it is printed, so that `--record FILE` writes
// it to a Markdown file (docs/results/) headed by where it came from: the
// command line, the commit, the machine and the date. The docs link these files
// instead of copying their numbers (docs/results/README.md).
//
// A record is Markdown: a title, a list of `- key: value` lines (command, commit,
// machine, date), then the benchmark's own paragraphs and tables. parseRecord
// reads it back and checks it (tests/bench/results_record_test.cpp reads every
// file of docs/results/ with it).
#include <cstdarg>
#include <filesystem>
#include <string>
#include <vector>

namespace lucent {

class ResultsRecord {
public:
    // argv as the process got it; `--record FILE` is left out of the command
    // line written to the record (it says where the record went, not what ran).
    // The title is name, or argv[0]'s file name; the command line starts with it.
    ResultsRecord(int argc, const char* const* argv, std::string name = "");
    // The same, from this process's own command line (/proc/self/cmdline): for
    // a subcommand that never sees argv (lucent bench accuracy).
    static ResultsRecord ofThisProcess(std::string name);

    // printf to standard output (flushed, so a long benchmark shows its rows as
    // they come) and into the record.
    void print(const char* format, ...) __attribute__((format(printf, 2, 3)));
    // A Markdown table's header and its alignment row; numeric columns right-aligned.
    void tableHeader(const std::vector<std::string>& columns, const std::vector<bool>& numeric = {});
    void tableRow(const std::vector<std::string>& cells);

    // What ran the work beside the processor, for the machine line: the OpenGL
    // renderer, the OpenCL device.
    void addDevice(const std::string& device);

    // The whole record: the header lines, then everything printed.
    std::string text() const;
    // Writes text() to file, whole or not at all (core/atomic_file.h).
    void write(const std::filesystem::path& file) const;

private:
    std::string name_, command_, body_;
    std::vector<std::string> devices_;
};

// One number in a printf format, for a table's cell.
std::string formatted(const char* format, double v);

// The commit of the source tree the benchmark was built from (git describe of
// LUCENT_SOURCE_DIR), "+ uncommitted changes" when the tree differs from it.
std::string sourceCommit();
// The processor, its cores and the memory: "AMD EPYC 7B13, 2 cores, 23.4 GiB".
std::string machineDescription();

// A record read back. Throws Error naming the file and the line that is wrong.
struct ParsedRecord {
    std::string title, command, commit, machine, date;
    struct Table {
        std::vector<std::string> header;
        std::vector<std::vector<std::string>> rows;
    };
    std::vector<Table> tables;
};
ParsedRecord parseRecord(const std::string& text, const std::string& file);

}  // namespace lucent
