#pragma once
// The viewer's own shaders (tonemap.frag), embedded at build time.
#include <string_view>

namespace lucent {

const char* viewerShader(std::string_view file);

}  // namespace lucent
