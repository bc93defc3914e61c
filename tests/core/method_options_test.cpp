// A method's options: defaults from the declaration, and every value a user can
// type checked against its domain before any method sees it.
#include "core/method_options.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace lucent {
namespace {

MethodOptions declared() {
    return MethodOptions({OptionSpec::integer("samples", 64, 1, 1 << 24, "paths per pixel"),
                          OptionSpec::integerOf("directions", 48, {24, 48, 80}, "directions"),
                          OptionSpec::real("noise", 0.0, 0.0, 1.0, "noise target"),
                          OptionSpec::choice("light", "traced", {"traced", "sh"}, "light")});
}

TEST(MethodOptions, DefaultsComeFromTheDeclaration) {
    const MethodOptions o = declared();
    EXPECT_EQ(o.integer("samples"), 64);
    EXPECT_EQ(o.integer("directions"), 48);
    EXPECT_EQ(o.real("noise"), 0.0);
    EXPECT_EQ(o.choice("light"), "traced");
}

TEST(MethodOptions, ValuesInTheirDomainAreTaken) {
    MethodOptions o = declared();
    o.set("samples", "16777216").set("directions", "80").set("noise", "0.05").set("light", "sh");
    EXPECT_EQ(o.integer("samples"), 1 << 24);
    EXPECT_EQ(o.integer("directions"), 80);
    EXPECT_DOUBLE_EQ(o.real("noise"), 0.05);
    EXPECT_EQ(o.choice("light"), "sh");
    o.set("samples", 4096.0).set("noise", 1e-3);
    EXPECT_EQ(o.integer("samples"), 4096);
    EXPECT_DOUBLE_EQ(o.real("noise"), 1e-3);
    EXPECT_EQ(o.real("samples"), 4096.0);  // an integer reads as a number too
}

TEST(MethodOptions, HostileValuesAreOneErrorNamingTheOption) {
    const std::pair<const char*, const char*> bad[] = {
        {"samples", "0"},
        {"samples", "16777217"},
        {"samples", "12x"},
        {"samples", ""},
        {"samples", "1e3"},
        {"samples", " 5"},
        {"samples", "99999999999999999999"},
        {"directions", "50"},
        {"noise", "nan"},
        {"noise", "inf"},
        {"noise", "-0.1"},
        {"noise", "1.0000001"},
        {"noise", "0.1 "},
        {"light", "Traced"},
        {"light", ""},
    };
    for (const auto& [name, value] : bad) {
        MethodOptions o = declared();
        try {
            o.set(name, value);
            ADD_FAILURE() << name << " took '" << value << "'";
        } catch (const Error& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(std::string("--") + name + " ", 0), 0u) << what;
            EXPECT_NE(what.find("expected"), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
    MethodOptions o = declared();
    EXPECT_THROW(o.set("noise", std::numeric_limits<double>::quiet_NaN()), Error);
    EXPECT_THROW(o.set("samples", 2.5), Error);  // not a whole number
    EXPECT_EQ(o.integer("samples"), 64) << "a refused value leaves the option as it was";
}

TEST(MethodOptions, UndeclaredNamesAreErrorsNotSilentlyIgnored) {
    MethodOptions o = declared();
    try {
        o.set("sample", "5");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(),
                     "option --sample is not one of this method's (--samples, --directions, --noise, --light)");
    }
    EXPECT_THROW(o.integer("grid"), Error);
    EXPECT_THROW(o.integer("light"), Error);  // read as the wrong type
    EXPECT_THROW(MethodOptions().set("grid", "8"), Error);
}

TEST(MethodOptions, DomainsReadAsHelp) {
    EXPECT_EQ(OptionSpec::integer("grid", 64, 8, 1024, "").domain(), "an integer in [8, 1024]");
    EXPECT_EQ(OptionSpec::integerOf("moments", 16, {4, 9, 16}, "").domain(), "one of 4, 9, 16");
    EXPECT_EQ(OptionSpec::real("tolerance", 1e-3, 1e-8, 0.5, "").domain(), "a number in [1e-08, 0.5]");
    EXPECT_EQ(OptionSpec::real("tolerance", 1e-3, 1e-8, 0.5, "").defaultValue, "0.001");
}

}  // namespace
}  // namespace lucent
