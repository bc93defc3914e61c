#pragma once
// Strict JSON reading for Lucent's input files (scenes, transport problems):
// duplicate keys refused, every key read or reported as unknown, every number
// finite and in range, each error one line naming the file and the key's path.
// Private to core/.
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/limits.h"
#include "core/math.h"

namespace lucent {

using Json = nlohmann::json;

// Parses text, refusing a key that repeats within one object (JSON would keep
// the last one silently; a file that says sigma_t twice is a mistake).
nlohmann::json parseStrictJson(const std::string& text, const std::string& fileName);

// Walks one JSON object, remembering its path for messages and which keys were
// read, so that any key left over (a typo) is reported.
class Node {
public:
    Node(const Json& json, std::string path, const std::string& file)
        : json_(json), path_(std::move(path)), file_(file) {}

    [[noreturn]] void fail(const std::string& problem) const {
        throw Error(file_, (path_.empty() ? std::string("/") : path_) + ": " + problem);
    }
    const std::string& path() const { return path_; }

    void requireObject() const {
        if (!json_.is_object()) fail("must be an object");
    }
    bool has(const std::string& key) {
        known_.insert(key);
        return json_.contains(key);
    }
    Node child(const std::string& key) {
        known_.insert(key);
        if (!json_.contains(key)) fail("missing required key '" + key + "'");
        return Node(json_.at(key), path_ + "/" + key, file_);
    }
    Node element(size_t i) const { return Node(json_.at(i), path_ + "/" + std::to_string(i), file_); }
    size_t arraySize() const {
        if (!json_.is_array()) fail("must be an array");
        return json_.size();
    }
    void rejectUnknownKeys() const {
        for (auto it = json_.begin(); it != json_.end(); ++it)
            if (!known_.count(it.key())) Node(it.value(), path_ + "/" + it.key(), file_).fail("unknown key");
    }

    double number() const {
        if (!json_.is_number()) fail("must be a number");
        const double v = json_.get<double>();
        if (!std::isfinite(v)) fail("must be finite");
        return v;
    }
    double number(double lo, double hi) const {
        const double v = number();
        if (v < lo || v > hi) fail("must lie in [" + fmt(lo) + ", " + fmt(hi) + "] (got " + fmt(v) + ")");
        return v;
    }
    double nonNegative() const {
        const double v = number();
        if (v < 0.0) fail("must be non-negative (got " + fmt(v) + ")");
        return v;
    }
    int integer(int lo, int hi) const {
        if (!json_.is_number_integer()) fail("must be an integer");
        const auto v = json_.get<long long>();
        if (v < lo || v > hi) fail("must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return int(v);
    }
    bool boolean() const {
        if (!json_.is_boolean()) fail("must be true or false");
        return json_.get<bool>();
    }
    std::string string() const {
        if (!json_.is_string()) fail("must be a string");
        return json_.get<std::string>();
    }
    Vec3 vec3() const {
        if (!json_.is_array() || json_.size() != 3) fail("must be an array of 3 numbers");
        return Vec3(element(0).number(), element(1).number(), element(2).number());
    }
    // A point of the scene: each coordinate within +-kMaxCoordinate.
    Vec3 point() const {
        if (!json_.is_array() || json_.size() != 3) fail("must be an array of 3 numbers");
        return Vec3(element(0).number(-kMaxCoordinate, kMaxCoordinate),
                    element(1).number(-kMaxCoordinate, kMaxCoordinate),
                    element(2).number(-kMaxCoordinate, kMaxCoordinate));
    }
    // A direction: not zero, returned unit length however large its components
    // (divided by the largest first, so that [1e200, 0, 0] does not overflow).
    Vec3 direction() const {
        const Vec3 d = vec3();
        const double largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        if (!(largest > 0.0)) fail("must not be the zero vector");
        return glm::normalize(d / largest);
    }
    // A number or an RGB triple, each channel within [lo, hi].
    Rgb rgb(double lo, double hi) const {
        if (json_.is_number()) {
            const double v = number(lo, hi);
            return Rgb(v);
        }
        if (!json_.is_array() || json_.size() != 3) fail("must be a number or an array of 3 numbers");
        return Rgb(element(0).number(lo, hi), element(1).number(lo, hi), element(2).number(lo, hi));
    }
    const Json& json() const { return json_; }

    static std::string fmt(double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    }

private:
    const Json& json_;
    std::string path_;
    const std::string& file_;
    std::set<std::string> known_;
};

}  // namespace lucent
