// The methods' own options as command-line flags: built from each method's
// declaration (core/method_options.h), never written out here.
#include "apps/commands.h"
#include "methods/method_table.h"

namespace lucent {

void addMethodOptions(CLI::App& sub, std::map<std::string, std::string>& values,
                      std::map<std::string, CLI::Option*>& flags) {
    for (const OfferedOption& offered : offeredOptions()) {
        const OptionSpec& spec = offered.spec;
        std::string methods;
        for (const std::string& m : offered.methods) methods += (methods.empty() ? "" : ", ") + m;
        const std::string help =
            "--method " + methods + ": " + spec.help + " (" + spec.domain() + "; default " + spec.defaultValue + ")";
        const CLI::Validator check(
            [spec](std::string& value) -> std::string {
                return spec.problem(value).empty() ? std::string() : "'" + value + "' is not " + spec.domain();
            },
            "");
        const char* type = spec.kind == OptionSpec::Kind::Choice    ? "CHOICE"
                           : spec.kind == OptionSpec::Kind::Integer ? "INT"
                                                                    : "FLOAT";
        flags[spec.name] = sub.add_option("--" + spec.name, values[spec.name], help)->check(check)->type_name(type);
    }
}

std::map<std::string, std::string> givenMethodOptions(const std::map<std::string, std::string>& values,
                                                      const std::map<std::string, CLI::Option*>& flags) {
    std::map<std::string, std::string> given;
    for (const auto& [name, flag] : flags)
        if (flag->count() > 0) given[name] = values.at(name);
    return given;
}

}  // namespace lucent
