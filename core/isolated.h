#pragma once
// Third-party readers (OpenMesh's PLY header parser, OpenVDB's decompression)
// crash or assert on some corrupt files, as fuzz/ found. Lucent cannot harden
// them, so it reads such a file once in a forked child first: a child that dies
// tells the parent the file is corrupt, and the parent never runs the read
// that would kill it.
#include <functional>
#include <string>

namespace lucent {

// Runs work in a forked child and waits at most timeoutSeconds (a reader can
// also loop forever: OpenMesh's PLY header parser does on some keywords).
// Returns "" when the child finished (whatever work threw), else how it died
// ("signal 11 (Segmentation fault)") or "no answer after N s" (it is killed).
std::string deathInChild(const std::function<void()>& work, double timeoutSeconds);

}  // namespace lucent
