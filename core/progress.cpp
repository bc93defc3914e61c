#include "core/progress.h"

#include <unistd.h>

#include <cstdio>

namespace lucent {
namespace {

thread_local std::shared_ptr<const ProgressSink> threadSink;

}  // namespace

ProgressSink setThreadProgressSink(ProgressSink sink) {
    ProgressSink previous = threadSink ? *threadSink : ProgressSink{};
    threadSink = sink ? std::make_shared<const ProgressSink>(std::move(sink)) : nullptr;
    return previous;
}

Progress::Progress(std::string stage, size_t total)
    : stage_(std::move(stage)),
      total_(total ? total : 1),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_),
      terminal_(::isatty(STDERR_FILENO) != 0),
      sink_(threadSink) {}

Progress::~Progress() {
    if (printed_) print(total_, true);
}

void Progress::advance(size_t n) {
    const size_t done = done_.fetch_add(n) + n;
    const auto now = std::chrono::steady_clock::now();
    // A terminal gets a live line; a log gets a line every few seconds.
    const double interval = terminal_ || sink_ ? 0.25 : 5.0;
    if (std::chrono::duration<double>(now - start_).count() < 1.0) return;
    if (std::chrono::duration<double>(now - lastPrint_).count() < interval) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    lastPrint_ = now;
    print(done, false);
}

void Progress::print(size_t done, bool final) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double fraction = std::min(1.0, double(done) / double(total_));
    printed_ = true;
    if (sink_) {
        (*sink_)(stage_, final ? 1.0 : fraction, final);
        return;
    }
    const char* end = terminal_ && !final ? "\r" : "\n";
    if (final)
        std::fprintf(stderr, "lucent: %s: done in %.1f s        %s", stage_.c_str(), elapsed, end);
    else {
        const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        std::fprintf(stderr, "lucent: %s: %3.0f%%, about %.0f s left   %s", stage_.c_str(), 100.0 * fraction, left,
                     end);
    }
    std::fflush(stderr);
}

}  // namespace lucent
