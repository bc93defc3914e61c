#include "apps/mpi_ranks.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.h"

#ifdef LUCENT_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C interface only: the C++ bindings are deprecated and need their own library
#include <mpi.h>
#endif

namespace lucent {
namespace {

// The ranks mpirun (OpenMPI) started, from the environment it gives each
// process: 0 when this process was not started by mpirun.
int launchedRanks() {
    const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
    if (!size) size = std::getenv("PMI_SIZE");
    return size ? std::atoi(size) : 0;
}

}  // namespace

Ranks::Ranks() {
    const int launched = launchedRanks();
    if (launched <= 1) return;
#ifdef LUCENT_HAVE_MPI
    MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    joined_ = true;
#else
    throw Error("mpirun",
                "this lucent was built without MPI, so " + std::to_string(launched) +
                    " ranks would each render the whole image; install libopenmpi-dev (scripts/install-deps.sh) "
                    "and build again (docs/mpi.md)");
#endif
}

Ranks::~Ranks() {
#ifdef LUCENT_HAVE_MPI
    if (joined_) MPI_Finalize();
#endif
}

Ranks::Verdict Ranks::agree(bool failedHere) const {
    Verdict v{failedHere, failedHere};
#ifdef LUCENT_HAVE_MPI
    if (!joined_) return v;
    // The lowest failing rank reports; size_ stands for "no failure".
    const int mine = failedHere ? rank_ : size_;
    int lowest = size_;
    MPI_Allreduce(&mine, &lowest, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    v.anyFailed = lowest < size_;
    v.reportHere = lowest == rank_;
#endif
    return v;
}

void Ranks::leaveIfAnyFailed(const std::string& failure) const {
    const Verdict verdict = agree(!failure.empty());
    if (!verdict.anyFailed) return;
    if (verdict.reportHere) throw Error(failure);
    throw QuietExit{0};
}

void Ranks::sumIntoRankZero(Image& image) const {
#ifdef LUCENT_HAVE_MPI
    if (!joined_) return;
    // Each pixel is rendered by one rank and 0 elsewhere, so the sum is exact.
    float* data = reinterpret_cast<float*>(image.pixels.data());
    const int count = int(image.pixels.size() * 3);
    if (rank_ == 0)
        MPI_Reduce(MPI_IN_PLACE, data, count, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
    else
        MPI_Reduce(data, nullptr, count, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
#else
    (void)image;
#endif
}

#ifdef LUCENT_HAVE_MPI
namespace {
// MPI counts are ints: long messages go in pieces.
constexpr size_t kMostPerMessage = size_t(1) << 30;
}  // namespace
#endif

void Ranks::send(int to, const float* values, size_t count) const {
#ifdef LUCENT_HAVE_MPI
    for (size_t at = 0; at < count; at += kMostPerMessage)
        MPI_Send(values + at, int(std::min(kMostPerMessage, count - at)), MPI_FLOAT, to, 0, MPI_COMM_WORLD);
#else
    (void)to, (void)values, (void)count;
    throw Error("internal: send without MPI");
#endif
}

void Ranks::receive(int from, float* values, size_t count) const {
#ifdef LUCENT_HAVE_MPI
    for (size_t at = 0; at < count; at += kMostPerMessage)
        MPI_Recv(values + at, int(std::min(kMostPerMessage, count - at)), MPI_FLOAT, from, 0, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
#else
    (void)from, (void)values, (void)count;
    throw Error("internal: receive without MPI");
#endif
}

void Ranks::sum(double* values, int count) const {
#ifdef LUCENT_HAVE_MPI
    if (!joined_) return;
    // Summed on rank 0 and sent out: an all-reduce may round differently on different ranks.
    if (rank_ == 0)
        MPI_Reduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    else
        MPI_Reduce(values, nullptr, count, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Bcast(values, count, MPI_DOUBLE, 0, MPI_COMM_WORLD);
#else
    (void)values, (void)count;
#endif
}

void Ranks::abortJob(const std::string& why) const {
#ifdef LUCENT_HAVE_MPI
    if (joined_) {
        std::fprintf(stderr, "lucent: error: %s\n", why.c_str());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
#endif
    throw Error(why);
}

}  // namespace lucent
