// The transport problem file (docs/transport.md): what it accepts, its
// defaults, and one error line naming the file and the key for anything else.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/transport_problem.h"

namespace lucent {
namespace {

std::string problem(const std::string& regions, const std::string& extra = "") {
    return R"({"domain": {"min": [0, 0, 0], "max": [2, 1, 1], "cells": [4, 2, 2]},
               "regions": [)" +
           regions + R"(], "points": [[1, 0.5, 0.5]])" + extra + "}";
}

TEST(TransportProblem, ReadsEveryKeyWithItsDefaults) {
    const TransportProblem p = parseTransportProblemText(
        problem(R"({"min": [0, 0, 0], "max": [2, 1, 1], "sigma_t": 2, "sigma_s": 1.5, "g": 0.3, "source": 4})",
                R"(, "boundary": {"x-": "reflective", "z+": "vacuum"}, "solver": {"directions": 120, "bands": 2,
                   "iterations": 7, "tolerance": 0.01, "uncollided": "swept"})"),
        "p.json");
    EXPECT_EQ(p.cells, (std::array<int, 3>{4, 2, 2}));
    EXPECT_EQ(p.reflective, (std::array<bool, 6>{true, false, false, false, false, false}));
    ASSERT_EQ(p.regions.size(), 1u);
    EXPECT_EQ(p.regions[0].sigmaT, 2.0);
    EXPECT_EQ(p.regions[0].sigmaS, 1.5);
    EXPECT_EQ(p.regions[0].g, 0.3);
    EXPECT_EQ(p.regions[0].source, 4.0);
    EXPECT_EQ(p.directions, 120);
    EXPECT_EQ(p.bands, 2);
    EXPECT_EQ(p.maxIterations, 7);
    EXPECT_EQ(p.tolerance, 0.01);
    EXPECT_EQ(p.uncollided, TransportProblem::Uncollided::Swept);
    const TransportProblem d =
        parseTransportProblemText(problem(R"({"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1})"), "d.json");
    EXPECT_EQ(d.regions[0].sigmaS, 0.0);
    EXPECT_EQ(d.regions[0].source, 0.0);
    EXPECT_EQ(d.reflective, (std::array<bool, 6>{}));  // vacuum all round
    EXPECT_EQ(d.uncollided, TransportProblem::Uncollided::Auto);
}

TEST(TransportProblem, RefusesWhatIsNotAProblem) {
    const std::string region = R"({"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1})";
    const std::pair<std::string, std::string> cases[] = {
        {problem(region, R"(, "extra": 1)"), "/extra: unknown key"},
        {problem(R"({"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": -1})"), "/regions/0/sigma_t: must lie in"},
        {problem(R"({"min": [0, 0, 0], "max": [0, 1, 1], "sigma_t": 1})"), "/regions/0: min must be below max"},
        {problem(R"({"min": [0, 0, 0], "max": [1, 1, 1], "sigma_t": 1, "g": 1})"), "/regions/0/g: must lie in"},
        {problem(region, R"(, "boundary": {"x-": "periodic"})"), "/boundary/x-: must be \"vacuum\" or \"reflective\""},
        {problem(region, R"(, "solver": {"bands": 7})"), "/solver/bands: must lie in [1, 6]"},
        {problem(region, R"(, "solver": {"uncollided": "first"})"),
         "/solver/uncollided: must be \"auto\", \"marched\" or \"swept\""},
        {R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [1024, 1024, 1024]}, "regions": [],
            "points": [[0.5, 0.5, 0.5]]})",
         "/domain/cells: asks for more than 2^24 cells"},
        {R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [2, 2, 2]}, "regions": [],
            "points": [[0.5, 0.5, 1.5]]})",
         "/points/0: lies outside the domain"},
        {R"({"domain": {"min": [0, 0, 0], "max": [1, 1, 1], "cells": [2, 2, 2]}, "regions": [], "points": []})",
         "/points: must hold at least one point"},
    };
    for (const auto& [text, message] : cases) {
        try {
            parseTransportProblemText(text, "bad.json");
            ADD_FAILURE() << "accepted: " << message;
        } catch (const Error& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind("bad.json: ", 0), 0u) << what;
            EXPECT_NE(what.find(message), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

}  // namespace
}  // namespace lucent
