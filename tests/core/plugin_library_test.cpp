// Opening plug-ins (core/plugin_library.h): a plug-in that is missing, or that
// lacks its entry point, is one Error naming the file, never a crash.
#include "core/plugin_library.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace lucent {
namespace {

// An address inside liblucent_core: its plug-ins sit beside it.
const void* coreAnchor() { return reinterpret_cast<const void*>(&pluginTable); }

std::string errorOpening(const std::string& file, const char* entry) {
    try {
        pluginTable(file, entry, coreAnchor());
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return {};
}

TEST(PluginLibrary, AMissingPlugInIsAnErrorNamingItsPath) {
    const std::string message = errorOpening("liblucent_absent.so", "lucentAbsent");
    EXPECT_NE(message.find("liblucent_absent.so: cannot load plug-in"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(PluginLibrary, APlugInWithoutTheEntryPointIsAnError) {
    const std::string message = errorOpening("liblucent_core_openvdb.so", "lucentNoSuchEntry");
    EXPECT_NE(message.find("liblucent_core_openvdb.so: plug-in has no entry point lucentNoSuchEntry"),
              std::string::npos)
        << message;
}

}  // namespace
}  // namespace lucent
