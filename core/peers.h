#pragma once
// The other processes of an MPI job, as a solver that shares its work with them
// sees them (docs/mpi.md). apps/mpi_ranks.h implements it with MPI; the
// solvers below apps/ know only this.
#include <cstddef>

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
};

}  // namespace lucent
