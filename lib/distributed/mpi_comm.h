#pragma once
// The MPI calls the data-parallel renderer makes, on MPI_COMM_WORLD, from one thread (TBB
// threads trace between the calls; MPI_THREAD_FUNNELED). Only this file and mpi_comm.cpp include
// <mpi.h>, so the rest of the library and the programs see plain C++ types.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "distributed/network_fabric.h"
#include "util/error.h"

namespace proxyvis {

// An error another rank reported: rank 0 prints it and exits with its code. The programs catch
// this before runApp would and return kExitOk on this rank: a non-zero exit here made mpirun
// abort the job, and when this rank was faster, rank 0 was killed before its message reached the
// terminal (the job's exit code is rank 0's either way). exitCode() is the job's code.
class ReportedOnAnotherRank : public Error {
 public:
  explicit ReportedOnAnotherRank(int code) : Error("", "reported by rank 0"), code_(code) {}
  int exitCode() const override { return code_; }

 private:
  int code_;
};

class MpiComm {
 public:
  // MPI_Init_thread on construction, MPI_Finalize on destruction (one per process).
  MpiComm(int* argc, char*** argv);
  ~MpiComm();
  MpiComm(const MpiComm&) = delete;
  MpiComm& operator=(const MpiComm&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // The host this rank runs on (MPI_Get_processor_name).
  std::string hostName() const;

  void barrier() const;
  // Element-wise reductions over all ranks, in place.
  void sum(std::span<double> v) const;
  void sum(std::span<uint64_t> v) const;
  void sum(std::span<float> v, bool to_root_only) const;  // float: images (one rank non-zero)
  void max(std::span<uint64_t> v) const;
  void max(std::span<double> v) const;
  void min(std::span<float> v) const;
  void max(std::span<float> v) const;
  // Per element the pair with the smallest value, ties to the smallest key (MPI_MINLOC).
  struct ValueKey {
    float value;
    int key;
  };
  void minLoc(std::span<ValueKey> v) const;
  void broadcast(std::span<uint8_t> bytes, int root) const;
  // Every rank's text, in rank order, on rank 0 (empty elsewhere).
  std::vector<std::string> gatherToRoot(const std::string& text) const;

  // Every rank calls this with its own error (nullopt if it has none). If any rank has one, the
  // first such rank's message (prefixed "rank R: " unless every rank failed) is thrown as an
  // Error on rank 0 with its exit code, and every other rank throws ReportedOnAnotherRank;
  // otherwise returns.
  void agree(const std::optional<Error>& error) const;
  // Runs `step`, turning an Error it throws into agree()'s collective error.
  template <typename F>
  void collectively(F&& step) const {
    std::optional<Error> error;
    try {
      step();
    } catch (const Error& e) {
      error = e;
    }
    agree(error);
  }

  // Whether every rank runs on this rank's host (the emulated fabric compares clocks).
  bool oneHost() const;
  // This machine's fabric between ranks 0 and 1, measured by ping-pong (the median round trip of
  // 32-byte messages, and of 1 MiB ones): {alpha in us, beta in GB/s} on every rank; {0, 0} with
  // one rank. Collective.
  std::pair<double, double> measureFabric() const;

  // One round of ray forwarding: sends outbox[r] (segments as raw bytes, `bytes_per_item` each)
  // to rank r, receives every rank's requests, answers them with `answer` (one byte per request,
  // called once per sender as its requests arrive) and returns each outbox's answers in replies[r]
  // in the same order. First one small collective (MPI_Alltoall) gives every rank the counts it
  // will receive and every rank's `open` segments (their sum is how rounds end: 0 everywhere);
  // then non-blocking sends and receives, one message per non-empty pair and direction.
  // With `emulate`, the exchange takes at least what that fabric charges: the count exchange
  // ends no earlier than ceil(log2 P) alpha after the last rank entered it, and this rank's
  // messages leave its link one after another, each posted no earlier than alpha + bytes / beta
  // after the previous one (or after it was ready). Needs every rank on one host (oneHost()).
  struct RoundStats {
    uint64_t items_sent = 0, bytes_sent = 0, messages_sent = 0;  // requests and answers
    uint64_t items_answered = 0, answer_bytes_sent = 0, answer_messages_sent = 0;
    uint64_t open_total = 0;  // sum of every rank's `open`
    double seconds = 0;       // wall time inside the round, answering excluded
    double answer_seconds = 0, answer_cpu_seconds = 0;  // answering (process CPU: all threads)
    double emulated_wait_seconds = 0;  // time spent holding messages back for the fabric
  };
  using Answer = void (*)(void* context, const uint8_t* requests, size_t count, uint8_t* answers);
  RoundStats exchange(const std::vector<std::vector<uint8_t>>& outbox, size_t bytes_per_item,
                      uint64_t open, Answer answer, void* context,
                      std::vector<std::vector<uint8_t>>& replies,
                      const NetworkFabric* emulate = nullptr) const;

  // Ends the whole job at once (a rank that cannot go on after the collective steps).
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace proxyvis
