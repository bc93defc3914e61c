// runProgram: exit codes, what a finished program used (wait4), and the errors
// for a program that cannot start. The truths are the programs' own: `true` and
// `false` exit 0 and 1, and dd reading /dev/zero fills a buffer of bs bytes,
// so its peak resident set holds at least that much. Linux keeps a process's
// peak across exec, and posix_spawn runs the child in the parent's memory until
// then: the figure is never below this test's own resident set (55 MB under
// AddressSanitizer), so the large buffer is larger than that.
#include <gtest/gtest.h>

#include "core/run_program.h"
#include "core/error.h"

namespace lucent {
namespace {

TEST(RunProgram, ReturnsTheExitCode) {
    EXPECT_EQ(runProgram({"true"}), 0);
    EXPECT_EQ(runProgram({"false"}), 1);
}

TEST(RunProgram, ReportsThePeakResidentSetAndProcessorTime) {
    ProgramUsage small, large;
    ASSERT_EQ(runProgram({"dd", "if=/dev/zero", "of=/dev/null", "bs=1k", "count=1"}, "/dev/null", &small), 0);
    ASSERT_EQ(runProgram({"dd", "if=/dev/zero", "of=/dev/null", "bs=160M", "count=1"}, "/dev/null", &large), 0);
    EXPECT_GE(large.peakResidentKb, 160 * 1024);  // the buffer dd filled
    EXPECT_LT(small.peakResidentKb, 160 * 1024);  // not a figure left from another program
    EXPECT_GT(large.cpuSeconds, 0.0);             // filling 160 MB takes some of it
    EXPECT_GE(small.cpuSeconds, 0.0);
}

TEST(RunProgram, NamesAProgramThatCannotStart) {
    try {
        runProgram({"lucent-no-such-program"});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("lucent-no-such-program"), std::string::npos) << e.what();
    }
    EXPECT_THROW(siblingProgram("lucent-no-such-program"), Error);
}

}  // namespace
}  // namespace lucent
