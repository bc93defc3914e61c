#pragma once
// OpenVDB's reader asserts, runs out of memory or never returns on some corrupt
// files, as fuzz/grid_fuzzer.cpp found. Lucent cannot harden it, so it reads a
// VDB file once in a forked child first: a child that dies tells the parent the
// file is corrupt, and the parent never runs the read that would kill it.
// (OpenMesh's crashes were all in its PLY header parser, which a strict header
// check now shields: core/mesh_file_check.h.)
#include <functional>
#include <string>

namespace lucent {

// Runs work in a forked child and waits at most timeoutSeconds (a reader can
// also loop forever).
// Returns "" when the child finished (whatever work threw), else how it died
// ("signal 11 (Segmentation fault)") or "no answer after N s" (it is killed).
std::string deathInChild(const std::function<void()>& work, double timeoutSeconds);

}  // namespace lucent
