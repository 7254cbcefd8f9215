// The ranks of an MPI job as Penumbra uses them: who we are (rank, host, rank on the host), a few
// collectives, small messages for the frame queue, and ending the whole job with one line.
// comm_mpi.cpp is the only file that includes mpi.h; comm_none.cpp stands in when MPI was not
// built (start() then throws a UsageError saying so).
//
// Waiting ranks sleep between polls instead of spinning as MPI's blocking calls do: ranks often
// share cores with lavapipe or with each other, and a spinning rank steals the renderers' time.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace penumbra::distributed {

class Comm {
public:
    // MPI_Init_thread (asking for threads, see canShareWithThread) with errors returned as codes.
    static std::unique_ptr<Comm> start();
    ~Comm();  // MPI_Finalize
    Comm(const Comm&) = delete;
    Comm& operator=(const Comm&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool primary() const { return rank_ == 0; }
    int localRank() const { return localRank_; }  // among the ranks on this host
    const std::string& host() const { return hosts_[std::size_t(rank_)]; }
    const std::string& hostOf(int rank) const { return hosts_.at(std::size_t(rank)); }
    // Whether a second thread may make MPI calls while the main thread makes none (rank 0's
    // frame server); MPI_THREAD_SERIALIZED or better.
    bool canShareWithThread() const { return threads_; }

    // Collectives: every rank calls them in the same order.
    void barrier();
    std::vector<std::string> allGather(const std::string& mine);
    void sumOnPrimary(std::span<double> values);  // rank 0 gets the sums over ranks in place
    void sumEverywhere(std::span<double> values);
    bool primaryDecides(bool value);  // rank 0's value, on every rank

    // Point to point, for small messages of integers.
    void send(int to, int tag, std::span<const std::int64_t> values);
    // A waiting message with `tag` from any rank, if there is one.
    bool tryReceive(int tag, int* from, std::vector<std::int64_t>& values);
    std::vector<std::int64_t> receive(int from, int tag);

    // Prints "penumbra: error: rank R on HOST: <message>" and ends every rank of the job
    // (MPI_Abort) with exitCode. For failures after setup, when other ranks may be waiting on
    // this one.
    [[noreturn]] void fail(const std::string& message, int exitCode);

private:
    Comm() = default;
    int rank_ = 0, size_ = 1, localRank_ = 0;
    bool threads_ = false;
    std::vector<std::string> hosts_;
};

}  // namespace penumbra::distributed
