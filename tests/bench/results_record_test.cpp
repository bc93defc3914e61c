// The records the benchmarks write with --record (bench/results_record.h), and
// every one committed in docs/results/: each parses, names the command that
// wrote it, its commit, machine and date, and holds well-formed tables.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/results_record.h"
#include "core/error.h"

namespace {

namespace fs = std::filesystem;
using lucent::Error;
using lucent::ParsedRecord;
using lucent::parseRecord;
using lucent::ResultsRecord;

std::string readAll(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The programs that write records, by the title they give them.
bool isBenchmark(const std::string& title) {
    for (const char* name :
         {"lucent-bench-render", "lucent-bench-preprocess", "lucent-bench-command", "lucent-bench-hybrid",
          "lucent-bench-peer", "lucent-bench-gallery", "lucent-bench-path", "lucent-bench-placement",
          "lucent-bench-grazing", "lucent-bench-environment", "lucent-bench-refraction-shapes",
          "lucent-bench-transport", "lucent-bench-scaling", "lucent bench accuracy", "time-ci.sh"})
        if (title == name) return true;
    return false;
}

TEST(ResultsRecord, WhatABenchmarkPrintsParsesBackWithItsCommandLine) {
    const char* argv[] = {
        "/somewhere/build/bin/lucent-bench-render", "--frames", "3", "--record", "out.md", "--backend", "a b"};
    ResultsRecord out(7, argv);
    out.addDevice("egl: llvmpipe");
    out.print("a paragraph\n\n");
    out.tableHeader({"samples", "frame (ms)"}, {true, true});
    out.tableRow({"25000", "136.0"});
    out.print("| %d | %.1f |\n", 50000, 170.25);
    const ParsedRecord r = parseRecord(out.text(), "record");
    EXPECT_EQ(r.title, "lucent-bench-render");
    // --record and its value are where the record went, not what ran.
    EXPECT_EQ(r.command, "lucent-bench-render --frames 3 --backend \"a b\"");
    EXPECT_FALSE(r.commit.empty());
    EXPECT_NE(r.machine.find("cores"), std::string::npos) << r.machine;
    EXPECT_NE(r.machine.find("egl: llvmpipe"), std::string::npos) << r.machine;
    ASSERT_EQ(r.tables.size(), 1u);
    EXPECT_EQ(r.tables[0].header, (std::vector<std::string>{"samples", "frame (ms)"}));
    ASSERT_EQ(r.tables[0].rows.size(), 2u);
    EXPECT_EQ(r.tables[0].rows[1], (std::vector<std::string>{"50000", "170.2"}));
}

TEST(ResultsRecord, WritesWholeOrNotAtAll) {
    const fs::path dir = fs::temp_directory_path() / ("lucent-record-test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const char* argv[] = {"lucent-bench-preprocess"};
    ResultsRecord out(1, argv);
    EXPECT_THROW(out.write(dir / "empty.md"), Error) << "a record without a table is refused, not written";
    EXPECT_FALSE(fs::exists(dir / "empty.md"));
    out.tableHeader({"directions"}, {true});
    out.tableRow({"64"});
    out.write(dir / "written.md");
    EXPECT_EQ(parseRecord(readAll(dir / "written.md"), "written.md").tables.at(0).rows.size(), 1u);
    fs::remove_all(dir);
}

TEST(ResultsRecord, MalformedRecordsAreRefusedNamingTheLine) {
    const std::string head =
        "# lucent-bench-render\n\n- command: `lucent-bench-render`\n- commit: abc\n- machine: m\n"
        "- date: 2026-12-03 10:00 UTC\n\n";
    const std::string table = "| a | b |\n|---|---:|\n| 1 | 2 |\n";
    EXPECT_NO_THROW(parseRecord(head + table, "good.md"));
    auto refused = [&](const std::string& text, const std::string& says) {
        try {
            parseRecord(text, "bad.md");
            ADD_FAILURE() << "accepted: " << says;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("bad.md"), std::string::npos) << e.what();
        }
    };
    refused(head + "| a | b |\n|---|---:|\n| 1 | 2 | 3 |\n", "line 10: a row of 3 cells in a table of 2 columns");
    refused(head + "| a | b |\n| 1 | 2 |\n", "alignment row");
    refused(head + "| a | b |\n", "a table with a header and nothing below it");
    refused(head, "no table of results");
    refused("lucent-bench-render\n" + table, "the first line is not");
    std::string noCommand = head;
    noCommand.replace(noCommand.find("- command"), 9, "- comand");
    refused(noCommand + table, "no '- command:");
    std::string otherCommand = head;
    otherCommand.replace(otherCommand.find("`lucent-bench-render`"), 21, "`lucent-bench-hybrid`");
    refused(otherCommand + table, "is not the benchmark of the title");
    std::string noDate = head;
    noDate.replace(noDate.find("2026-12-03 10:00 UTC"), 20, "yesterday");
    refused(noDate + table, "no '- date:");
}

TEST(ResultsRecord, EveryRecordInDocsResultsParsesAndNamesItsCommand) {
    const fs::path dir = fs::path(LUCENT_SOURCE_DIR) / "docs/results";
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    int records = 0;
    std::vector<fs::path> files = {fs::path(LUCENT_SOURCE_DIR) / "docs/gallery.md"};  // a record with pictures
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".md" && entry.path().filename() != "README.md") files.push_back(entry.path());
    for (const fs::path& file : files) {
        ++records;
        SCOPED_TRACE(file.filename().string());
        ParsedRecord r;
        ASSERT_NO_THROW(r = parseRecord(readAll(file), file.string()));
        EXPECT_TRUE(isBenchmark(r.title)) << "written by " << r.title << ", which is no benchmark of Lucent";
        EXPECT_EQ(r.command.rfind(r.title, 0), 0u) << r.command;
        EXPECT_GT(r.tables.front().rows.size(), 0u);
        for (const ParsedRecord::Table& t : r.tables)
            for (const auto& row : t.rows)
                for (const std::string& cell : row) {
                    const size_t at = cell.find("](");
                    if (cell.rfind("![", 0) != 0 || at == std::string::npos) continue;
                    EXPECT_TRUE(fs::is_regular_file(file.parent_path() / cell.substr(at + 2, cell.size() - at - 3)))
                        << "the picture of " << cell;
                }
    }
    EXPECT_GE(records, 1) << "docs/results/ holds no record";
}

}  // namespace
