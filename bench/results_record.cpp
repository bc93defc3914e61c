#include "bench/results_record.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_program.h"

namespace lucent {
namespace {

std::string vformat(const char* format, va_list args) {
    va_list copy;
    va_copy(copy, args);
    const int size = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string text(size_t(std::max(size, 0)), '\0');
    std::vsnprintf(text.data(), text.size() + 1, format, args);
    return text;
}

std::string trim(const std::string& s) {
    const size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// A program's first line of output, or empty when it fails or says nothing.
std::string firstLineOf(const std::vector<std::string>& argv) {
    char dir[] = "/tmp/lucent-record-XXXXXX";
    if (!::mkdtemp(dir)) return "";
    const std::filesystem::path log = std::filesystem::path(dir) / "out";
    std::string line;
    try {
        if (runProgram(argv, log) == 0) {
            std::ifstream in(log);
            std::getline(in, line);
        }
    } catch (const Error&) {
        line.clear();  // no git: the commit is unknown
    }
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
    return trim(line);
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
    return text;
}

// "| a | b |" -> {"a", "b"}; a cell may hold a code span with "\|" in it.
std::vector<std::string> cellsOf(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    for (size_t i = 1; i + 1 < line.size(); ++i) {
        if (line[i] == '\\' && line[i + 1] == '|') {
            cell += '|';
            ++i;
        } else if (line[i] == '|') {
            cells.push_back(trim(cell));
            cell.clear();
        } else {
            cell += line[i];
        }
    }
    cells.push_back(trim(cell));
    return cells;
}

bool isAlignmentRow(const std::vector<std::string>& cells) {
    for (const std::string& c : cells)
        if (c.empty() || c.find_first_not_of(":-") != std::string::npos || c.find('-') == std::string::npos)
            return false;
    return true;
}

}  // namespace

ResultsRecord::ResultsRecord(int argc, const char* const* argv, std::string name) : name_(std::move(name)) {
    command_ = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "benchmark";
    if (name_.empty()) name_ = command_;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--record") {
            ++i;  // and its value
            continue;
        }
        if (arg.rfind("--record=", 0) == 0) continue;
        command_ += ' ';
        command_ += arg.find_first_of(" \t\"'") == std::string::npos ? arg : "\"" + arg + "\"";
    }
}

ResultsRecord ResultsRecord::ofThisProcess(std::string name) {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::vector<std::string> words;
    for (std::string word; std::getline(in, word, '\0');) words.push_back(word);
    std::vector<const char*> argv;
    for (const std::string& w : words) argv.push_back(w.c_str());
    return ResultsRecord(int(argv.size()), argv.data(), std::move(name));
}

void ResultsRecord::print(const char* format, ...) {
    va_list args;
    va_start(args, format);
    const std::string text = vformat(format, args);
    va_end(args);
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
    body_ += text;
}

void ResultsRecord::tableHeader(const std::vector<std::string>& columns, const std::vector<bool>& numeric) {
    std::string header = "|", alignment = "|";
    for (size_t k = 0; k < columns.size(); ++k) {
        header += " " + columns[k] + " |";
        alignment += k < numeric.size() && numeric[k] ? "---:|" : "---|";
    }
    print("%s\n%s\n", header.c_str(), alignment.c_str());
}

void ResultsRecord::tableRow(const std::vector<std::string>& cells) {
    std::string row = "|";
    for (const std::string& c : cells) row += " " + c + " |";
    print("%s\n", row.c_str());
}

void ResultsRecord::addDevice(const std::string& device) { devices_.push_back(device); }

std::string ResultsRecord::text() const {
    std::string machine = machineDescription();
    for (const std::string& d : devices_) machine += "; " + d;
    std::string code = command_;
    std::replace(code.begin(), code.end(), '`', '\'');  // a backquote would end the code span
    return "# " + name_ + "\n\n" +                      //
           "- command: `" + code + "`\n" +              //
           "- commit: " + sourceCommit() + "\n" +       //
           "- machine: " + machine + "\n" +             //
           "- date: " + utcNow() + "\n\n" + body_;
}

void ResultsRecord::write(const std::filesystem::path& file) const {
    const std::string content = text();
    parseRecord(content, file.string());  // a benchmark never writes a record its test would refuse
    AtomicFile out(file);
    out.stream() << content;
    out.commit();
    std::fprintf(stderr, "%s: recorded in %s\n", name_.c_str(), file.c_str());
}

std::string formatted(const char* format, double v) {
    char text[32];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

std::string sourceCommit() {
    const std::string dir = LUCENT_SOURCE_DIR;
    const std::string commit = firstLineOf({"git", "-C", dir, "rev-parse", "--short=12", "HEAD"});
    if (commit.empty()) return "unknown (not built from a git checkout)";
    // Other records written beside this one are no change to what ran.
    const std::string changed = firstLineOf(
        {"git", "-C", dir, "status", "--porcelain", "--untracked-files=no", "--", ".", ":(exclude)docs/results"});
    return changed.empty() ? commit : commit + " + uncommitted changes";
}

std::string machineDescription() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown processor";
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
            model = trim(line.substr(line.find(':') + 1));
            break;
        }
    std::ifstream meminfo("/proc/meminfo");
    double kib = 0.0;
    while (std::getline(meminfo, line))
        if (line.rfind("MemTotal:", 0) == 0) {
            kib = std::atof(line.substr(9).c_str());
            break;
        }
    char text[256];
    std::snprintf(text, sizeof text, "%s, %u cores, %.1f GiB", model.c_str(), std::thread::hardware_concurrency(),
                  kib / (1024.0 * 1024.0));
    return text;
}

ParsedRecord parseRecord(const std::string& text, const std::string& file) {
    ParsedRecord record;
    std::istringstream in(text);
    std::string line;
    int n = 0;
    auto fail = [&](const std::string& problem) { throw Error(file, "line " + std::to_string(n) + ": " + problem); };
    ParsedRecord::Table* table = nullptr;
    bool expectAlignment = false;
    while (std::getline(in, line)) {
        ++n;
        if (n == 1) {
            if (line.rfind("# ", 0) != 0 || trim(line.substr(2)).empty()) fail("the first line is not '# BENCHMARK'");
            record.title = trim(line.substr(2));
            continue;
        }
        for (auto [key, field] : {std::pair{"- command: ", &record.command}, std::pair{"- commit: ", &record.commit},
                                  std::pair{"- machine: ", &record.machine}, std::pair{"- date: ", &record.date}})
            if (line.rfind(key, 0) == 0 && field->empty()) *field = trim(line.substr(std::string(key).size()));
        const std::string t = trim(line);
        if (t.size() >= 2 && t.front() == '|' && t.back() == '|') {
            const std::vector<std::string> cells = cellsOf(t);
            if (!table) {
                record.tables.push_back({cells, {}});
                table = &record.tables.back();
                expectAlignment = true;
            } else if (expectAlignment) {
                if (!isAlignmentRow(cells)) fail("a table's second row is not its alignment row (|---|---:|)");
                if (cells.size() != table->header.size())
                    fail("the alignment row has " + std::to_string(cells.size()) + " cells, the header " +
                         std::to_string(table->header.size()));
                expectAlignment = false;
            } else {
                if (cells.size() != table->header.size())
                    fail("a row of " + std::to_string(cells.size()) + " cells in a table of " +
                         std::to_string(table->header.size()) + " columns");
                table->rows.push_back(cells);
            }
        } else {
            if (table && expectAlignment) fail("a table with a header and nothing below it");
            table = nullptr;
        }
    }
    if (table && expectAlignment) fail("a table with a header and nothing below it");
    n = 0;
    if (record.command.size() < 3 || record.command.front() != '`' || record.command.back() != '`')
        fail("no '- command: `...`' line naming the command that wrote it");
    record.command = record.command.substr(1, record.command.size() - 2);
    if (record.command.rfind(record.title, 0) != 0)
        fail("the command `" + record.command + "` is not the benchmark of the title, " + record.title);
    if (record.commit.empty()) fail("no '- commit: ' line");
    if (record.machine.empty()) fail("no '- machine: ' line");
    if (record.date.size() != 20 || record.date.substr(16) != " UTC") fail("no '- date: YYYY-MM-DD HH:MM UTC' line");
    if (record.tables.empty()) fail("no table of results");
    return record;
}

}  // namespace lucent
