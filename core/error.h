#pragma once
// One error type for everything a user can get wrong. The message is what the
// command line prints after "lucent: error: ", so it always names the file
// (and, for scene files, the JSON path) and the problem in one line.
#include <stdexcept>
#include <string>

namespace lucent {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
    Error(const std::string& file, const std::string& problem)
        : std::runtime_error(file + ": " + problem) {}
};

}  // namespace lucent
