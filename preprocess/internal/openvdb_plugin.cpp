#include "preprocess/internal/openvdb_plugin.h"

#include "core/plugin_library.h"

namespace lucent {

namespace {
const char kAnchor = 0;  // an address inside liblucent_preprocess
}  // namespace

const PreprocessOpenVdbPlugin& preprocessOpenVdbPlugin() {
    static const auto* table = static_cast<const PreprocessOpenVdbPlugin*>(
        pluginTable("liblucent_preprocess_openvdb.so", "lucentPreprocessOpenVdbPlugin", &kAnchor));
    return *table;
}

}  // namespace lucent
