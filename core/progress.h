#pragma once
// Progress of long work on stderr: stage, percentage and estimated time left.
// Silent for work that finishes within a second; thread-safe advance().
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace lucent {

// Where progress goes instead of stderr: a host (the Python module) sets a sink
// on the thread that starts the work; each Progress made on that thread then
// reports (stage, fraction done, whether it is the last report) to it, from
// whichever thread advances it, at most four times a second.
using ProgressSink = std::function<void(const std::string& stage, double fraction, bool final)>;
// Sets this thread's sink (an empty one: stderr again); returns the previous one.
ProgressSink setThreadProgressSink(ProgressSink sink);

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
    std::shared_ptr<const ProgressSink> sink_;  // this thread's at construction, or none
};

}  // namespace lucent
