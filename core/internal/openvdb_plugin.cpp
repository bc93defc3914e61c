#include "core/internal/openvdb_plugin.h"

#include "core/plugin_library.h"

namespace lucent {

namespace {
const char kAnchor = 0;  // an address inside liblucent_core
}  // namespace

const CoreOpenVdbPlugin& coreOpenVdbPlugin() {
    static const auto* table = static_cast<const CoreOpenVdbPlugin*>(
        pluginTable("liblucent_core_openvdb.so", "lucentCoreOpenVdbPlugin", &kAnchor));
    return *table;
}

}  // namespace lucent
