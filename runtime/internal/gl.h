#pragma once
// The one way Lucent's own code reaches OpenGL: the glad 4.5 core loader, its
// names prefixed lucent_ (runtime/CMakeLists.txt) so that they never meet a
// host's loader. Private: no installed header includes it.
#include <lucent_glad/gl.h>
