#pragma once
// The other processes of an MPI job, as a solver that shares its work with them
// sees them (docs/mpi.md). apps/mpi_ranks.h implements it with MPI; the
// solvers below apps/ know only this.
#include <cstddef>
#include <string>

namespace lucent {

class Peers {
public:
    virtual ~Peers() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    // Point to point and blocking; the receiver knows how many values come.
    virtual void send(int to, const float* values, size_t count) const = 0;
    virtual void receive(int from, float* values, size_t count) const = 0;
    // Every rank's values summed, the same bits on every rank (summed on rank 0
    // and sent out, so that every rank takes the same decisions from them).
    virtual void sum(double* values, int count) const = 0;
    // A failure where the other ranks may be waiting for this one: says why in
    // one error line and ends every rank of the job.
    [[noreturn]] virtual void abort(const std::string& why) const = 0;
};

// Thrown by a rank whose shared work stopped because another rank failed
// before the ranks started to talk: that rank says why; this one leaves
// without a word of its own.
struct PeerFailed {};

}  // namespace lucent
