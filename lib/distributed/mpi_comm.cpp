#include "distributed/mpi_comm.h"

#include <mpi.h>

#include <chrono>
#include <cstring>

#include "util/stopwatch.h"

namespace proxyvis {

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int checkedCount(size_t n) {
  PV_CHECK_MSG(n <= size_t(INT32_MAX), "MPI message above 2 GiB");
  return int(n);
}

constexpr int kRequestTag = 11, kReplyTag = 12;

// Every rank's `v` combined element-wise by `op`, in place on every rank.
template <class T>
void allReduce(std::span<T> v, MPI_Datatype type, MPI_Op op) {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), checkedCount(v.size()), type, op, MPI_COMM_WORLD);
}

}  // namespace

MpiComm::MpiComm(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiComm::~MpiComm() {
  MPI_Finalize();
}

std::string MpiComm::hostName() const {
  char name[MPI_MAX_PROCESSOR_NAME];
  int len = 0;
  MPI_Get_processor_name(name, &len);
  return std::string(name, size_t(len));
}

void MpiComm::barrier() const {
  MPI_Barrier(MPI_COMM_WORLD);
}

void MpiComm::sum(std::span<double> v) const {
  allReduce(v, MPI_DOUBLE, MPI_SUM);
}
void MpiComm::sum(std::span<uint64_t> v) const {
  allReduce(v, MPI_UINT64_T, MPI_SUM);
}
void MpiComm::sum(std::span<float> v, bool to_root_only) const {
  if (!to_root_only) {
    allReduce(v, MPI_FLOAT, MPI_SUM);
  } else if (rank_ == 0) {
    MPI_Reduce(MPI_IN_PLACE, v.data(), checkedCount(v.size()), MPI_FLOAT, MPI_SUM, 0,
               MPI_COMM_WORLD);
  } else {
    MPI_Reduce(v.data(), nullptr, checkedCount(v.size()), MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
  }
}
void MpiComm::max(std::span<uint64_t> v) const {
  allReduce(v, MPI_UINT64_T, MPI_MAX);
}
void MpiComm::max(std::span<double> v) const {
  allReduce(v, MPI_DOUBLE, MPI_MAX);
}
void MpiComm::min(std::span<float> v) const {
  allReduce(v, MPI_FLOAT, MPI_MIN);
}
void MpiComm::max(std::span<float> v) const {
  allReduce(v, MPI_FLOAT, MPI_MAX);
}
void MpiComm::minLoc(std::span<ValueKey> v) const {
  static_assert(sizeof(ValueKey) == sizeof(float) + sizeof(int));
  allReduce(v, MPI_FLOAT_INT, MPI_MINLOC);
}
void MpiComm::broadcast(std::span<uint8_t> bytes, int root) const {
  MPI_Bcast(bytes.data(), checkedCount(bytes.size()), MPI_BYTE, root, MPI_COMM_WORLD);
}

std::vector<std::string> MpiComm::gatherToRoot(const std::string& text) const {
  int length = checkedCount(text.size());
  std::vector<int> lengths(size_t(size_), 0), offsets(size_t(size_), 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  size_t total = 0;
  for (size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = int(total);
    total += size_t(lengths[r]);
  }
  std::string all(rank_ == 0 ? total : 0, '\0');
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, MPI_COMM_WORLD);
  std::vector<std::string> out;
  if (rank_ != 0) return out;
  for (size_t r = 0; r < lengths.size(); ++r)
    out.push_back(all.substr(size_t(offsets[r]), size_t(lengths[r])));
  return out;
}

void MpiComm::agree(const std::optional<Error>& error) const {
  // The first failing rank, by a min-reduction of (rank if failed, else size).
  int first = error ? rank_ : size_, failed = error ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == size_) return;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  // That rank sends its message and exit code to rank 0.
  std::string text;
  int code = kExitBadInput;
  if (rank_ == first) {
    text = error->what();
    code = error->exitCode();
  }
  int header[2] = {int(text.size()), code};
  MPI_Bcast(header, 2, MPI_INT, first, MPI_COMM_WORLD);
  text.resize(size_t(header[0]));
  MPI_Bcast(text.data(), header[0], MPI_CHAR, first, MPI_COMM_WORLD);
  if (rank_ != 0) throw ReportedOnAnotherRank(header[1]);
  struct RankError : Error {
    RankError(std::string what, int code) : Error("", std::move(what)), code_(code) {}
    int exitCode() const override { return code_; }
    int code_;
  };
  // An error every rank has (a bad flag, a scene file) is not about one rank: no prefix.
  throw RankError(failed == size_ ? text : "rank " + std::to_string(first) + ": " + text,
                  header[1]);
}

MpiComm::RoundStats MpiComm::exchange(const std::vector<std::vector<uint8_t>>& outbox,
                                      size_t bytes_per_item, Answer answer, void* context,
                                      std::vector<std::vector<uint8_t>>& replies) const {
  RoundStats stats;
  const double start = now();
  const size_t n = size_t(size_);
  PV_CHECK(outbox.size() == n);
  std::vector<uint64_t> send_counts(n), recv_counts(n);
  for (size_t r = 0; r < n; ++r) send_counts[r] = outbox[r].size() / bytes_per_item;
  MPI_Alltoall(send_counts.data(), 1, MPI_UINT64_T, recv_counts.data(), 1, MPI_UINT64_T,
               MPI_COMM_WORLD);

  // Requests out, requests in.
  std::vector<std::vector<uint8_t>> inbox(n);
  std::vector<MPI_Request> recv_req, send_req;
  std::vector<int> recv_from;
  for (size_t r = 0; r < n; ++r) {
    if (recv_counts[r] == 0) continue;
    inbox[r].resize(recv_counts[r] * bytes_per_item);
    recv_req.emplace_back();
    recv_from.push_back(int(r));
    MPI_Irecv(inbox[r].data(), checkedCount(inbox[r].size()), MPI_BYTE, int(r), kRequestTag,
              MPI_COMM_WORLD, &recv_req.back());
  }
  replies.assign(n, {});
  std::vector<MPI_Request> reply_recv;
  for (size_t r = 0; r < n; ++r) {
    if (send_counts[r] == 0) continue;
    send_req.emplace_back();
    MPI_Isend(outbox[r].data(), checkedCount(outbox[r].size()), MPI_BYTE, int(r), kRequestTag,
              MPI_COMM_WORLD, &send_req.back());
    stats.items_sent += send_counts[r];
    stats.bytes_sent += outbox[r].size();
    stats.messages_sent += 1;
    replies[r].resize(send_counts[r]);
    reply_recv.emplace_back();
    MPI_Irecv(replies[r].data(), checkedCount(replies[r].size()), MPI_BYTE, int(r), kReplyTag,
              MPI_COMM_WORLD, &reply_recv.back());
  }

  // Answer each sender as its requests arrive, and send the answers back at once.
  std::vector<std::vector<uint8_t>> answers(n);
  std::vector<MPI_Request> answer_req;
  answer_req.reserve(recv_req.size());
  for (size_t done = 0; done < recv_req.size(); ++done) {
    int index = MPI_UNDEFINED;
    MPI_Waitany(int(recv_req.size()), recv_req.data(), &index, MPI_STATUS_IGNORE);
    const size_t r = size_t(recv_from[size_t(index)]);
    const double t0 = now(), c0 = processCpuSeconds();
    answers[r].resize(recv_counts[r]);
    answer(context, inbox[r].data(), recv_counts[r], answers[r].data());
    stats.answer_seconds += now() - t0;
    stats.answer_cpu_seconds += processCpuSeconds() - c0;
    answer_req.emplace_back();
    MPI_Isend(answers[r].data(), checkedCount(answers[r].size()), MPI_BYTE, int(r), kReplyTag,
              MPI_COMM_WORLD, &answer_req.back());
    stats.bytes_sent += answers[r].size();
    stats.messages_sent += 1;
  }
  MPI_Waitall(int(send_req.size()), send_req.data(), MPI_STATUSES_IGNORE);
  MPI_Waitall(int(reply_recv.size()), reply_recv.data(), MPI_STATUSES_IGNORE);
  MPI_Waitall(int(answer_req.size()), answer_req.data(), MPI_STATUSES_IGNORE);
  stats.seconds = now() - start - stats.answer_seconds;
  return stats;
}

void MpiComm::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();
}

}  // namespace proxyvis
