#pragma once
// Progress of long work on stderr: stage, percentage and estimated time left.
// Silent for work that finishes within a second; thread-safe advance().
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace lucent {

class Progress {
public:
    Progress(std::string stage, size_t total);
    ~Progress();
    void advance(size_t done = 1);

private:
    void print(size_t done, bool final);
    std::string stage_;
    size_t total_;
    std::atomic<size_t> done_{0};
    std::chrono::steady_clock::time_point start_, lastPrint_;
    std::mutex mutex_;
    bool printed_ = false;
    bool terminal_;
};

}  // namespace lucent
