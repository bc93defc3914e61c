// The folder rules of docs/architecture.md, read from the sources themselves:
// each folder includes only the folders below it, and nothing outside runtime/
// (its white-box tests aside) includes the runtime's private headers.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kSource = LUCENT_SOURCE_DIR;

// What each folder may include besides itself. core is below everything; the
// four stages meet only through core; methods joins them; the viewer and the
// benchmarks sit on methods; the lucent command (apps) is the one place that
// joins the viewer and the benchmarks' sweep into subcommands.
const std::map<std::string, std::set<std::string>> kMayInclude = {
    {"core", {}},
    {"preprocess", {"core"}},
    {"reference", {"core"}},
    {"runtime", {"core"}},
    {"hybrid", {"core"}},
    {"methods", {"core", "preprocess", "reference", "runtime", "hybrid"}},
    {"viewer", {"core", "preprocess", "reference", "runtime", "hybrid", "methods"}},
    {"bench", {"core", "preprocess", "reference", "runtime", "hybrid", "methods"}},
    {"apps", {"core", "preprocess", "reference", "runtime", "hybrid", "methods", "viewer", "bench"}},
    {"examples", {"core", "preprocess", "runtime"}},
    {"python", {"core", "preprocess", "reference", "runtime", "hybrid", "methods"}},
};

struct Include {
    fs::path file;
    int line;
    std::string target;  // as written: "runtime/internal/gl.h"
};

std::vector<Include> projectIncludes(const fs::path& folder) {
    static const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::vector<Include> found;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
        std::ifstream in(entry.path());
        std::string text;
        for (int n = 1; std::getline(in, text); ++n)
            if (std::smatch m; std::regex_search(text, m, include)) found.push_back({entry.path(), n, m[1]});
    }
    return found;
}

std::string folderOf(const std::string& target) { return target.substr(0, target.find('/')); }

TEST(Layering, EachFolderIncludesOnlyTheFoldersBelowIt) {
    size_t checked = 0;
    for (const auto& [folder, allowed] : kMayInclude) {
        for (const Include& inc : projectIncludes(kSource / folder)) {
            const std::string target = folderOf(inc.target);
            if (!kMayInclude.count(target) || target == folder) continue;  // a system or generated header, or its own
            ++checked;
            EXPECT_TRUE(allowed.count(target))
                << fs::relative(inc.file, kSource).string() << ":" << inc.line << " includes " << inc.target << ": "
                << folder << "/ may not include " << target << "/";
        }
    }
    EXPECT_GT(checked, 100u) << "the scan found too few includes to mean anything";
}

TEST(Layering, OnlyTheRuntimeAndItsTestsIncludeItsInternals) {
    size_t scanned = 0;
    for (const auto& [folder, allowed] : kMayInclude) {
        if (folder == "runtime") continue;
        for (const Include& inc : projectIncludes(kSource / folder)) {
            ++scanned;
            EXPECT_EQ(inc.target.rfind("runtime/internal/", 0), std::string::npos)
                << fs::relative(inc.file, kSource).string() << ":" << inc.line << " includes " << inc.target;
        }
    }
    for (const auto& sub : fs::directory_iterator(kSource / "tests")) {
        if (!sub.is_directory() || sub.path().filename() == "runtime") continue;
        for (const Include& inc : projectIncludes(sub.path())) {
            ++scanned;
            EXPECT_EQ(inc.target.rfind("runtime/internal/", 0), std::string::npos)
                << fs::relative(inc.file, kSource).string() << ":" << inc.line << " includes " << inc.target;
        }
    }
    EXPECT_GT(scanned, 100u);
}

// The check can fail: a file that reaches past a public header is caught.
TEST(Layering, TheScanSeesAnIncludeOfTheInternals) {
    const fs::path dir = fs::temp_directory_path() / ("lucent-layering-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "bad.cpp") << "#include <vector>\n  #  include \"runtime/internal/gl.h\"  // reaching in\n";
    const std::vector<Include> found = projectIncludes(dir);
    fs::remove_all(dir);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].target, "runtime/internal/gl.h");
    EXPECT_EQ(found[0].line, 2);
}

}  // namespace
