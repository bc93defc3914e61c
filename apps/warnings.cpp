#include <cstdio>

#include "apps/commands.h"

namespace lucent {

void printWarnings(const std::vector<std::string>& warnings) {
    for (const auto& w : warnings) std::fprintf(stderr, "lucent: warning: %s\n", w.c_str());
}

}  // namespace lucent
