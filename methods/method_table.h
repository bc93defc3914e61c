#pragma once
// Every rendering method built into this binary, with its factory: the one list
// the command line, the viewer and the benchmarks read. A new method is a folder
// of its own implementing core/method.h plus one row in method_table.cpp.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/method.h"
#include "core/scene.h"

namespace lucent {

// The methods this build has, in the order --help lists them.
const std::vector<MethodEntry>& methodTable();
// Their names, then "auto".
std::vector<std::string> methodNames();
// The entry called name; Error listing the built methods otherwise.
const MethodEntry& findMethod(const std::string& name);

// What --method auto aims for, from the measurements of docs/accuracy.md
// ("What auto picks"): relative RMSE against full transport (--method path).
inline constexpr double kAutoGoal = 0.10;
// Single scattering alone stays within kAutoGoal of full transport up to this
// albedo (measured 6.5% on the sphere and 9.5% on the bunny at 0.1, 11% and 14% at 0.2).
inline constexpr double kSingleScatteringAlbedo = 0.1;
// Up to this |g| lbl stays near the goal (9-13% measured at g 0.4, 33-137% at 0.8).
inline constexpr double kLatticeMaxG = 0.5;
// Up to this |g| mdom stays within the goal (6.6% on the sphere and 8.8% on the
// bunny measured at g 0.8 and albedo 0.9, against a path-traced truth whose own
// noise is taken out; 32% on the sphere at 0.9).
inline constexpr double kMdomMaxG = 0.8;
// At a refracting boundary lbl stays within the goal on a lone smooth convex
// object (core/surface_shape.h) up to this albedo and for g in [min, max]
// (docs/results/refraction-shapes.md: 4-10% on a sphere, an ellipsoid and a
// capsule; 9-13% at albedo 0.95, 9-16% at g 0.3; by hand, 8-10% at albedo 0.9
// and 10% at g 0.15).
inline constexpr double kRefractingLatticeAlbedo = 0.8;
inline constexpr double kRefractingLatticeMinG = -0.3;
inline constexpr double kRefractingLatticeMaxG = 0.0;
// ... and an optical radius (sigma_t times the smallest half-extent of its box)
// in this range (9-11% at 0.5, 9-13% at 8; at 8 a capsule is optically thick,
// which ss draws index-matched).
inline constexpr double kRefractingLatticeOpticalRadius[2] = {1.0, 4.0};
// Up to this many pixels the CPU reference is as fast as ss on a software OpenGL.
inline constexpr long kReferenceAsFastPixels = 256 * 256;

// What --method auto picks for a scene, and why (printed to the user).
struct MethodChoice {
    std::string method;
    std::string reason;
};
MethodChoice chooseMethod(const SceneDesc& scene);
// Whether OpenGL here is a software rasteriser (Mesa's llvmpipe, softpipe,
// swrast) or missing: then ss has no speed over the CPU reference for small images.
bool openGlIsSoftware();

// One option as the command line offers it: its declaration, and the methods
// that declare it (lbl and mdom share ss's --light, say).
struct OfferedOption {
    OptionSpec spec;
    std::vector<std::string> methods;
};
// Every option of every method, in table order, each name once. Throws Error
// when two methods declare one name differently: one flag, one meaning.
std::vector<OfferedOption> offeredOptions();
// The entry's options with the given values (name to value, as typed) set.
// A value for an option the entry does not declare is an Error naming the
// methods that take it, unless the entry was chosen by auto: then it is left
// out with a line in warnings, since the user could not know which method runs.
MethodOptions methodOptions(const MethodEntry& entry, const std::map<std::string, std::string>& given,
                            bool chosenByAuto, std::vector<std::string>& warnings);

// Resolves "auto" and checks availability: the entry to run and, for auto, why.
struct ResolvedMethod {
    const MethodEntry* entry = nullptr;
    std::string reason;  // empty unless chosen by auto
};
ResolvedMethod resolveMethod(const std::string& name, const SceneDesc& scene);

// Creates the method and renders. servedBy receives what served the frame, if asked.
Image renderWith(const MethodEntry& entry, const LoadedScene& scene, const MethodSettings& settings,
                 std::string* servedBy = nullptr);
// Renders with a method entry.create() made (and perhaps prepared, Method::prepare).
Image renderWith(const MethodEntry& entry, Method& method, const LoadedScene& scene, const MethodSettings& settings,
                 std::string* servedBy = nullptr);

}  // namespace lucent
