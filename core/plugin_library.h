#pragma once
// Code whose libraries are slow to load lives in plug-in libraries that Lucent
// opens on first use. OpenVDB alone binds 57 000 symbols when a program starts,
// a cost every command paid though most never read or write a grid
// (docs/architecture.md). A plug-in sits beside the Lucent library that uses it
// and gives that library a table of functions through one entry point.
#include <string>

namespace lucent {

// Opens `fileName` from the directory of the library holding `anchor` (an
// address inside it) and returns what its function `entryPoint` returns. Opened
// once per process; throws Error naming the file if it cannot be.
const void* pluginTable(const std::string& fileName, const char* entryPoint, const void* anchor);

}  // namespace lucent
