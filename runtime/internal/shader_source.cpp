#include "runtime/internal/shader_source.h"

#include <set>

#include "core/error.h"

namespace lucent {
namespace {

void expand(const std::string& name, std::string_view text, const ShaderLookup& lookup, std::set<std::string>& seen,
            std::string& out, int depth) {
    if (depth > 16) throw Error(name, "GLSL #include nested too deeply");
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        constexpr std::string_view kInclude = "#include \"";
        if (line.substr(0, kInclude.size()) == kInclude && line.size() > kInclude.size() && line.back() == '"') {
            const std::string file(line.substr(kInclude.size(), line.size() - kInclude.size() - 1));
            const char* included = lookup(file);
            if (!included) throw Error(name, "GLSL #include of unknown file '" + file + "'");
            if (seen.insert(file).second) expand(name, included, lookup, seen, out, depth + 1);
        } else {
            out.append(line);
            out.push_back('\n');
        }
        start = end + 1;
    }
}

}  // namespace

std::string assembleShaderSource(const std::string& name, std::string_view source,
                                 const std::vector<std::string>& defines, const ShaderLookup& lookup) {
    const size_t eol = source.find('\n');
    if (source.substr(0, 9) != "#version " || eol == std::string_view::npos)
        throw Error(name, "GLSL source does not start with a #version line");
    std::string out(source.substr(0, eol + 1));
    for (const std::string& d : defines) out += "#define " + d + "\n";
    std::set<std::string> seen;
    expand(name, source.substr(eol + 1), lookup, seen, out, 0);
    return out;
}

}  // namespace lucent
