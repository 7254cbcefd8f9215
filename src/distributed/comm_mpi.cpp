#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "core/error.h"
#include "distributed/comm.h"

namespace penumbra::distributed {
namespace {

// MPI calls return codes (MPI_ERRORS_RETURN on the world); a failure becomes an Error naming the call.
void check(int code, const char* call) {
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw Error(std::string(call) + " failed: " + std::string(text, std::size_t(std::max(length, 0))));
}

// Polls a request until it completes, sleeping between polls (from 50 us up to 5 ms), so a rank
// that waits for slower ones leaves the CPU to them.
void waitGently(MPI_Request& request, const char* call) {
    auto pause = std::chrono::microseconds(50);
    while (true) {
        int done = 0;
        check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), call);
        if (done) return;
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(5000));
    }
}

int countOf(std::size_t n) {
    if (n > std::size_t(INT32_MAX)) throw Error("a message of " + std::to_string(n) + " values is too large for MPI");
    return int(n);
}

}  // namespace

std::unique_ptr<Comm> Comm::start() {
    int provided = MPI_THREAD_SINGLE;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided), "MPI_Init_thread");
    std::unique_ptr<Comm> comm(new Comm);
    check(MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler");
    comm->threads_ = provided >= MPI_THREAD_SERIALIZED;
    check(MPI_Comm_rank(MPI_COMM_WORLD, &comm->rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &comm->size_), "MPI_Comm_size");
    // The rank among the ranks that share this host's memory picks this host's GPU.
    MPI_Comm local = MPI_COMM_NULL;
    check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, comm->rank_, MPI_INFO_NULL, &local),
          "MPI_Comm_split_type");
    check(MPI_Comm_rank(local, &comm->localRank_), "MPI_Comm_rank");
    MPI_Comm_free(&local);
    char name[MPI_MAX_PROCESSOR_NAME];
    int length = 0;
    check(MPI_Get_processor_name(name, &length), "MPI_Get_processor_name");
    comm->hosts_ = comm->allGather(std::string(name, std::size_t(std::max(length, 0))));
    return comm;
}

Comm::~Comm() { MPI_Finalize(); }

void Comm::barrier() {
    MPI_Request request;
    check(MPI_Ibarrier(MPI_COMM_WORLD, &request), "MPI_Ibarrier");
    waitGently(request, "MPI_Ibarrier");
}

std::vector<std::string> Comm::allGather(const std::string& mine) {
    int length = countOf(mine.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_));
    MPI_Request request;
    check(MPI_Iallgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD, &request), "MPI_Iallgather");
    waitGently(request, "MPI_Iallgather");
    std::vector<int> offsets(static_cast<std::size_t>(size_));
    std::size_t total = 0;
    for (std::size_t r = 0; r < lengths.size(); ++r) {
        offsets[r] = countOf(total);
        total += std::size_t(lengths[r]);
    }
    std::string all(total, '\0');
    check(MPI_Iallgatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
                          MPI_COMM_WORLD, &request),
          "MPI_Iallgatherv");
    waitGently(request, "MPI_Iallgatherv");
    std::vector<std::string> out;
    for (std::size_t r = 0; r < lengths.size(); ++r) out.push_back(all.substr(std::size_t(offsets[r]), std::size_t(lengths[r])));
    return out;
}

// Large reductions: wait gently until every rank has arrived, then reduce with the blocking call,
// which MPI runs at full speed once everyone is there.
void Comm::sumOnPrimary(std::span<double> values) {
    barrier();
    void* send = primary() ? MPI_IN_PLACE : values.data();
    check(MPI_Reduce(send, values.data(), countOf(values.size()), MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD), "MPI_Reduce");
}

void Comm::sumEverywhere(std::span<double> values) {
    barrier();
    check(MPI_Allreduce(MPI_IN_PLACE, values.data(), countOf(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD),
          "MPI_Allreduce");
}

bool Comm::primaryDecides(bool value) {
    int v = value ? 1 : 0;
    MPI_Request request;
    check(MPI_Ibcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD, &request), "MPI_Ibcast");
    waitGently(request, "MPI_Ibcast");
    return v != 0;
}

void Comm::send(int to, int tag, std::span<const std::int64_t> values) {
    check(MPI_Send(values.data(), countOf(values.size()), MPI_INT64_T, to, tag, MPI_COMM_WORLD), "MPI_Send");
}

bool Comm::tryReceive(int tag, int* from, std::vector<std::int64_t>& values) {
    int waiting = 0;
    MPI_Status status;
    check(MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &waiting, &status), "MPI_Iprobe");
    if (!waiting) return false;
    int count = 0;
    check(MPI_Get_count(&status, MPI_INT64_T, &count), "MPI_Get_count");
    values.assign(std::size_t(std::max(count, 0)), 0);
    check(MPI_Recv(values.data(), count, MPI_INT64_T, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
          "MPI_Recv");
    *from = status.MPI_SOURCE;
    return true;
}

std::vector<std::int64_t> Comm::receive(int from, int tag) {
    MPI_Status status;
    auto pause = std::chrono::microseconds(50);
    while (true) {
        int waiting = 0;
        check(MPI_Iprobe(from, tag, MPI_COMM_WORLD, &waiting, &status), "MPI_Iprobe");
        if (waiting) break;
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(5000));
    }
    int count = 0;
    check(MPI_Get_count(&status, MPI_INT64_T, &count), "MPI_Get_count");
    std::vector<std::int64_t> values(std::size_t(std::max(count, 0)));
    check(MPI_Recv(values.data(), count, MPI_INT64_T, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    return values;
}

void Comm::fail(const std::string& message, int exitCode) {
    std::fprintf(stderr, "penumbra: error: rank %d on %s: %s\n", rank_, host().c_str(), message.c_str());
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, exitCode);
    std::_Exit(exitCode);  // MPI_Abort does not return; should it, this rank still ends
}

}  // namespace penumbra::distributed
