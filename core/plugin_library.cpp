#include "core/plugin_library.h"

#include <dlfcn.h>

#include <filesystem>

#include "core/error.h"

namespace lucent {

const void* pluginTable(const std::string& fileName, const char* entryPoint, const void* anchor) {
    Dl_info info{};
    if (dladdr(anchor, &info) == 0 || !info.dli_fname)
        throw Error(fileName, "cannot find the directory of the Lucent library that loads this plug-in");
    const std::filesystem::path file = std::filesystem::path(info.dli_fname).parent_path() / fileName;
    // RTLD_LOCAL: the plug-in's libraries stay out of the scope every later
    // symbol lookup searches. dlopen returns the same handle when called again.
    void* library = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* why = dlerror();
        throw Error(file.string(), std::string("cannot load plug-in: ") + (why ? why : "unknown error"));
    }
    using Entry = const void* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(library, entryPoint));
    if (!entry) throw Error(file.string(), std::string("plug-in has no entry point ") + entryPoint);
    return entry();
}

}  // namespace lucent
