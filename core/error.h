#pragma once
// One error type for everything a user can get wrong. The message is what the
// command line prints after "lucent: error: ", so it always names the file
// (and, for scene files, the JSON path) and the problem in one line: control
// characters (a NUL or a newline in a file name, say) are shown as \xHH, so that
// nothing cuts the message short or breaks it over lines.
#include <cstdio>
#include <stdexcept>
#include <string>

namespace lucent {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(printable(message)) {}
    Error(const std::string& file, const std::string& problem) : std::runtime_error(printable(file + ": " + problem)) {}

    static std::string printable(const std::string& text) {
        std::string out;
        out.reserve(text.size());
        for (const char c : text) {
            const auto byte = static_cast<unsigned char>(c);
            if (byte < 0x20 || byte == 0x7f) {
                char escaped[8];
                std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
                out += escaped;
            } else {
                out += c;
            }
        }
        return out;
    }
};

}  // namespace lucent
