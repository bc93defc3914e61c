#pragma once
// GLSL has no #include and no command-line defines: the runtime assembles each
// stage's text itself. Pure string work, tested without a GL context.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace lucent {

// Finds an included file's text by name (nullptr: no such file).
using ShaderLookup = std::function<const char*(std::string_view)>;

// source with `#define NAME` lines for defines inserted after its #version line,
// and every line `#include "FILE"` replaced by FILE's text from lookup (recursively;
// a file already included is left out, as with include guards). Throws Error
// naming `name` for a missing file or a source without a #version line.
std::string assembleShaderSource(const std::string& name, std::string_view source,
                                 const std::vector<std::string>& defines, const ShaderLookup& lookup);

}  // namespace lucent
