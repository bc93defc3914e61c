#pragma once
// Output files appear whole or not at all: writers write to a temporary file
// beside the target and rename it into place once everything has been written.
// A failure anywhere in between leaves no half-written file behind.
#include <filesystem>
#include <fstream>

namespace lucent {

class AtomicFile {
public:
    // Throws Error("TARGET: cannot write ...") if the temporary file cannot be created.
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();  // removes the temporary file unless commit() succeeded
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // For writers that open the file themselves (libpng, OpenEXR).
    const std::filesystem::path& temporaryPath() const { return temporary_; }
    // For writers that stream.
    std::ofstream& stream();
    void commit();

private:
    std::filesystem::path target_, temporary_;
    std::ofstream stream_;
    bool committed_ = false;
};

// Fails now, with the error writing would give later, if target cannot be written:
// commands call it before long work so a typo in a path costs nothing.
void checkWritable(const std::filesystem::path& target);

}  // namespace lucent
