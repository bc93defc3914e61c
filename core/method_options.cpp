#include "core/method_options.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.h"

namespace lucent {
namespace {

std::string formatNumber(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", x);
    return text;
}

// The whole text as an integer, or false.
bool parseInteger(const std::string& text, long long& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end && !text.empty();
}

// The whole text as a finite number, or false (no NaN, no infinity).
bool parseReal(const std::string& text, double& out) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(out);
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
    return out;
}

}  // namespace

OptionSpec OptionSpec::integer(std::string name, int value, int min, int max, std::string help) {
    return {std::move(name), Kind::Integer, std::to_string(value), double(min), double(max), {}, std::move(help)};
}

OptionSpec OptionSpec::integerOf(std::string name, int value, const std::vector<int>& values, std::string help) {
    std::vector<std::string> choices;
    for (int v : values) choices.push_back(std::to_string(v));
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return {std::move(name), Kind::Integer, std::to_string(value), double(*lo), double(*hi), choices, std::move(help)};
}

OptionSpec OptionSpec::real(std::string name, double value, double min, double max, std::string help) {
    return {std::move(name), Kind::Real, formatNumber(value), min, max, {}, std::move(help)};
}

OptionSpec OptionSpec::choice(std::string name, std::string value, std::vector<std::string> choices, std::string help) {
    return {std::move(name), Kind::Choice, std::move(value), 0.0, 0.0, std::move(choices), std::move(help)};
}

std::string OptionSpec::domain() const {
    if (!choices.empty()) return "one of " + joined(choices);
    const std::string range = "[" + formatNumber(min) + ", " + formatNumber(max) + "]";
    return (kind == Kind::Integer ? "an integer in " : "a number in ") + range;
}

std::string OptionSpec::problem(const std::string& value) const {
    const std::string wrong = "--" + name + " " + value + ": expected " + domain();
    if (!choices.empty()) return std::find(choices.begin(), choices.end(), value) != choices.end() ? "" : wrong;
    if (kind == Kind::Integer) {
        long long n = 0;
        return parseInteger(value, n) && double(n) >= min && double(n) <= max ? "" : wrong;
    }
    double x = 0.0;
    return parseReal(value, x) && x >= min && x <= max ? "" : wrong;
}

MethodOptions::MethodOptions(std::vector<OptionSpec> specs) : specs_(std::move(specs)) {
    for (const OptionSpec& s : specs_) values_[s.name] = s.defaultValue;
}

const OptionSpec& MethodOptions::spec(const std::string& name) const {
    for (const OptionSpec& s : specs_)
        if (s.name == name) return s;
    std::vector<std::string> names;
    for (const OptionSpec& s : specs_) names.push_back("--" + s.name);
    throw Error("option --" + name + " is not one of this method's (" +
                (names.empty() ? std::string("it has none") : joined(names)) + ")");
}

bool MethodOptions::declares(const std::string& name) const {
    return std::any_of(specs_.begin(), specs_.end(), [&](const OptionSpec& s) { return s.name == name; });
}

MethodOptions& MethodOptions::set(const std::string& name, const std::string& value) {
    const std::string problem = spec(name).problem(value);
    if (!problem.empty()) throw Error(problem);
    values_[name] = value;
    return *this;
}

MethodOptions& MethodOptions::set(const std::string& name, double value) {
    return set(name,
               spec(name).kind == OptionSpec::Kind::Integer && value == std::floor(value) && std::abs(value) < 1e15
                   ? std::to_string((long long)value)
                   : formatNumber(value));
}

int MethodOptions::integer(const std::string& name) const {
    if (spec(name).kind != OptionSpec::Kind::Integer) throw Error("option --" + name + " is not an integer");
    return std::stoi(values_.at(name));
}

double MethodOptions::real(const std::string& name) const {
    const OptionSpec& s = spec(name);
    if (s.kind == OptionSpec::Kind::Choice) throw Error("option --" + name + " is not a number");
    return std::strtod(values_.at(name).c_str(), nullptr);
}

const std::string& MethodOptions::choice(const std::string& name) const {
    if (spec(name).kind != OptionSpec::Kind::Choice) throw Error("option --" + name + " is not a choice");
    return values_.at(name);
}

}  // namespace lucent
