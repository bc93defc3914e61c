#pragma once
// lucent render under mpirun (docs/mpi.md): every rank parses and loads the
// scene, the methods that split rows (path, reference) render their share of
// the rows, and rank 0 sums the shares and writes the image; mdom shares its
// sweeps, and rank 0's image is the frame. Before anything is
// written every rank says whether it failed: a failure anywhere ends the job
// with a non-zero exit, one error line and no output, never a rank left
// waiting. The lowest failing rank prints the line and exits 1; the others
// exit 0 quietly, since mpirun kills the whole job at the first non-zero exit,
// which could cut off the line. A rank killed outright is mpirun's to end:
// it stops the job, and rank 0, waiting in the sum, writes nothing.
#include <string>

#include "core/image.h"
#include "core/peers.h"

namespace lucent {

class Ranks : public Peers {
public:
    // Joins the job when mpirun started this process; alone otherwise. A build
    // without MPI started by mpirun with more than one rank is an Error saying so.
    Ranks();
    ~Ranks() override;
    Ranks(const Ranks&) = delete;
    Ranks& operator=(const Ranks&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }
    void send(int to, const float* values, size_t count) const override;
    void receive(int from, float* values, size_t count) const override;
    void sum(double* values, int count) const override;
    [[noreturn]] void abort(const std::string& why) const override { abortJob(why); }

    // Collective: where any rank failed (failure: this rank's error, empty if
    // none), every rank leaves: the one to say why throws it as an Error, the
    // others QuietExit{0}, so that the reporting rank's status ends the job (a
    // second non-zero exit could make mpirun kill that rank before its line is out).
    void leaveIfAnyFailed(const std::string& failure) const;

    // Collective: every rank's image summed into rank 0's (the others' are left as they are).
    void sumIntoRankZero(Image& image) const;

    // A failure in the middle of shared work, where the other ranks may be
    // waiting for this one: says why in one error line and ends every rank of
    // the job (MPI_Abort). Alone, throws it as an Error.
    [[noreturn]] void abortJob(const std::string& why) const;

private:
    // Collective: whether any rank failed, and whether this rank is the one to say why.
    struct Verdict {
        bool anyFailed = false;
        bool reportHere = false;
    };
    Verdict agree(bool failedHere) const;

    int rank_ = 0, size_ = 1;
    bool joined_ = false;
};

// Thrown to leave with this exit code and print nothing (another rank reported).
struct QuietExit {
    int code = 1;
};

}  // namespace lucent
