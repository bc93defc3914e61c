#pragma once
// A method's own settings, declared beside the method (pbrt-v4's
// ParameterDictionary, read by each class's Create): every option has a name, a
// type, a range, a default and a line of help. The declaration is the one the
// command line, the benchmarks and `lucent methods` (docs/methods.md) are built
// from, so a new option is one line in its method and nowhere else.
#include <map>
#include <string>
#include <vector>

namespace lucent {

struct OptionSpec {
    enum class Kind { Integer, Real, Choice };
    std::string name;  // the command line's --NAME
    Kind kind = Kind::Integer;
    std::string defaultValue;          // as typed on the command line
    double min = 0.0, max = 0.0;       // Integer and Real: the inclusive range
    std::vector<std::string> choices;  // Choice, or an Integer that takes only these values
    std::string help;                  // one line: what it does and what it costs

    static OptionSpec integer(std::string name, int value, int min, int max, std::string help);
    static OptionSpec integerOf(std::string name, int value, const std::vector<int>& values, std::string help);
    static OptionSpec real(std::string name, double value, double min, double max, std::string help);
    static OptionSpec choice(std::string name, std::string value, std::vector<std::string> choices, std::string help);

    // Empty when value is one this option takes; otherwise what is wrong with it.
    std::string problem(const std::string& value) const;
    // What it takes, for help: "an integer in [1, 16777216]", "one of traced, sh".
    std::string domain() const;
    bool operator==(const OptionSpec&) const = default;
};

// The values of one method's options: the declared defaults, then what the
// caller set. Setting or reading a name the method does not declare throws Error,
// so a mistyped name never passes unnoticed.
class MethodOptions {
public:
    MethodOptions() = default;
    explicit MethodOptions(std::vector<OptionSpec> specs);

    // Throws Error naming the option when it is not declared or the value is out of its domain.
    MethodOptions& set(const std::string& name, const std::string& value);
    MethodOptions& set(const std::string& name, double value);
    bool declares(const std::string& name) const;

    int integer(const std::string& name) const;
    double real(const std::string& name) const;
    const std::string& choice(const std::string& name) const;
    const std::vector<OptionSpec>& specs() const { return specs_; }

private:
    const OptionSpec& spec(const std::string& name) const;
    std::vector<OptionSpec> specs_;
    std::map<std::string, std::string> values_;
};

}  // namespace lucent
