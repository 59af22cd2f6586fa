#include "distributed/mpi_comm.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>

#include "util/stopwatch.h"

namespace proxyvis {

namespace {

double now() {
  return steadySeconds();
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

bool MpiComm::oneHost() const {
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  int local_size = 0;
  MPI_Comm_size(local, &local_size);
  MPI_Comm_free(&local);
  int all = local_size == size_ ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

std::pair<double, double> MpiComm::measureFabric() const {
  double result[2] = {0, 0};
  if (size_ >= 2 && rank_ < 2) {
    const int other = 1 - rank_;
    // The median round trip of `trips` ping-pongs of `bytes` bytes (answered by 1 byte): the
    // median, because ranks sharing a core (more ranks than cores) see a few round trips wait
    // for a time slice.
    auto roundTrip = [&](size_t bytes, int trips) {
      std::vector<uint8_t> buffer(bytes, 0);
      std::vector<double> times;
      for (int i = 0; i < trips; ++i) {
        const double t = now();
        if (rank_ == 0) {
          MPI_Send(buffer.data(), checkedCount(bytes), MPI_BYTE, other, kRequestTag,
                   MPI_COMM_WORLD);
          MPI_Recv(buffer.data(), 1, MPI_BYTE, other, kReplyTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        } else {
          MPI_Recv(buffer.data(), checkedCount(bytes), MPI_BYTE, other, kRequestTag, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE);
          MPI_Send(buffer.data(), 1, MPI_BYTE, other, kReplyTag, MPI_COMM_WORLD);
        }
        times.push_back(now() - t);
      }
      std::nth_element(times.begin(), times.begin() + long(times.size() / 2), times.end());
      return times[times.size() / 2];
    };
    roundTrip(32, 20);  // warm-up: connections and buffers
    const double small = roundTrip(32, 200);
    const size_t big_bytes = size_t(1) << 20;
    const double big = roundTrip(big_bytes, 20);
    const double alpha = small / 2;  // one way; the 1-byte answer costs about alpha too
    result[0] = 1e6 * alpha;
    result[1] = double(big_bytes) / std::max(big - 2 * alpha, 1e-9) / 1e9;
  }
  MPI_Bcast(result, 2, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return {result[0], result[1]};
}

namespace {

// One round's control message per rank pair: the count of requests, the sender's open segments
// and the time it entered the round (all sent in one all-to-all).
struct RoundControl {
  std::vector<uint64_t> send_counts, recv_counts;
  uint64_t open_total = 0;
  uint64_t last_entered_ns = 0;
};

RoundControl exchangeControl(const std::vector<std::vector<uint8_t>>& outbox, size_t bytes_per_item,
                             uint64_t open, double entered) {
  constexpr size_t kControl = 3;
  const size_t n = outbox.size();
  std::vector<uint64_t> send(n * kControl), recv(n * kControl);
  RoundControl c;
  c.send_counts.resize(n);
  c.recv_counts.resize(n);
  for (size_t r = 0; r < n; ++r) {
    c.send_counts[r] = outbox[r].size() / bytes_per_item;
    send[r * kControl] = c.send_counts[r];
    send[r * kControl + 1] = open;
    send[r * kControl + 2] = uint64_t(std::llround(1e9 * entered));
  }
  MPI_Alltoall(send.data(), int(kControl), MPI_UINT64_T, recv.data(), int(kControl), MPI_UINT64_T,
               MPI_COMM_WORLD);
  for (size_t r = 0; r < n; ++r) {
    c.recv_counts[r] = recv[r * kControl];
    c.open_total += recv[r * kControl + 1];
    c.last_entered_ns = std::max(c.last_entered_ns, recv[r * kControl + 2]);
  }
  return c;
}

// This rank's outgoing link: messages leave in order, each once the (emulated) link has carried
// it; without emulation each leaves at once.
class OutgoingLink {
 public:
  OutgoingLink(const NetworkFabric* emulate, double free_at, MpiComm::RoundStats& stats)
      : emulate_(emulate), free_at_(free_at), stats_(stats) {}

  void enqueue(const std::vector<uint8_t>& data, int to, int tag, uint64_t items) {
    double release = 0;
    if (emulate_) {
      free_at_ = std::max(free_at_, now()) + emulate_->messageSeconds(data.size(), items);
      release = free_at_;
    }
    queue_.push_back({release, &data, to, tag});
    stats_.bytes_sent += data.size();
    stats_.messages_sent += 1;
  }

  // Posts every message whose release time has come.
  void postDue() {
    while (!queue_.empty() && queue_.front().release <= now()) {
      const Outgoing& o = queue_.front();
      sends_.emplace_back();
      MPI_Isend(o.data->data(), checkedCount(o.data->size()), MPI_BYTE, o.to, o.tag, MPI_COMM_WORLD,
                &sends_.back());
      queue_.pop_front();
    }
  }

  bool holding() const { return !queue_.empty(); }
  double nextRelease() const { return queue_.front().release; }
  void waitSent() { MPI_Waitall(int(sends_.size()), sends_.data(), MPI_STATUSES_IGNORE); }

 private:
  struct Outgoing {
    double release;
    const std::vector<uint8_t>* data;
    int to, tag;
  };
  const NetworkFabric* emulate_;
  double free_at_;
  MpiComm::RoundStats& stats_;
  std::deque<Outgoing> queue_;
  std::vector<MPI_Request> sends_;
};

}  // namespace

MpiComm::RoundStats MpiComm::exchange(const std::vector<std::vector<uint8_t>>& outbox,
                                      size_t bytes_per_item, uint64_t open, Answer answer,
                                      void* context, std::vector<std::vector<uint8_t>>& replies,
                                      const NetworkFabric* emulate) const {
  RoundStats stats;
  const double start = now();
  const size_t n = size_t(size_);
  PV_CHECK(outbox.size() == n);
  const RoundControl control = exchangeControl(outbox, bytes_per_item, open, start);
  stats.open_total = control.open_total;
  double link_free = 0;
  if (emulate) {
    link_free = 1e-9 * double(control.last_entered_ns) + emulate->collectiveSeconds(size_);
    stats.emulated_wait_seconds += waitUntilSteady(link_free);
  }
  replies.assign(n, {});
  if (stats.open_total == 0) {  // nothing pending anywhere: every count is 0
    stats.seconds = now() - start;
    return stats;
  }

  // Requests in.
  std::vector<std::vector<uint8_t>> inbox(n);
  std::vector<MPI_Request> recv_req;
  std::vector<int> recv_from;
  for (size_t r = 0; r < n; ++r) {
    if (control.recv_counts[r] == 0) continue;
    inbox[r].resize(control.recv_counts[r] * bytes_per_item);
    recv_req.emplace_back();
    recv_from.push_back(int(r));
    MPI_Irecv(inbox[r].data(), checkedCount(inbox[r].size()), MPI_BYTE, int(r), kRequestTag,
              MPI_COMM_WORLD, &recv_req.back());
  }
  // Requests out, and their answers in.
  OutgoingLink link(emulate, link_free, stats);
  std::vector<MPI_Request> reply_recv;
  for (size_t r = 0; r < n; ++r) {
    if (control.send_counts[r] == 0) continue;
    link.enqueue(outbox[r], int(r), kRequestTag, control.send_counts[r]);
    stats.items_sent += control.send_counts[r];
    replies[r].resize(control.send_counts[r]);
    reply_recv.emplace_back();
    MPI_Irecv(replies[r].data(), checkedCount(replies[r].size()), MPI_BYTE, int(r), kReplyTag,
              MPI_COMM_WORLD, &reply_recv.back());
  }

  // Answer each sender as its requests arrive, and send the answers back.
  std::vector<std::vector<uint8_t>> answers(n);
  auto answerFrom = [&](size_t r) {
    const double t0 = now(), c0 = processCpuSeconds();
    answers[r].resize(control.recv_counts[r]);
    answer(context, inbox[r].data(), control.recv_counts[r], answers[r].data());
    stats.answer_seconds += now() - t0;
    stats.answer_cpu_seconds += processCpuSeconds() - c0;
    stats.items_answered += control.recv_counts[r];
    link.enqueue(answers[r], int(r), kReplyTag, 0);
    stats.answer_bytes_sent += answers[r].size();
    stats.answer_messages_sent += 1;
  };
  size_t answered = 0;
  link.postDue();
  while (answered < recv_req.size() || link.holding()) {
    if (answered < recv_req.size()) {
      int index = MPI_UNDEFINED, arrived = 0;
      if (!link.holding()) {
        MPI_Waitany(int(recv_req.size()), recv_req.data(), &index, MPI_STATUS_IGNORE);
        arrived = index != MPI_UNDEFINED;
      } else {
        MPI_Testany(int(recv_req.size()), recv_req.data(), &index, &arrived, MPI_STATUS_IGNORE);
        arrived = arrived && index != MPI_UNDEFINED;
      }
      if (arrived) {
        answerFrom(size_t(recv_from[size_t(index)]));
        ++answered;
        link.postDue();
        continue;
      }
    }
    if (link.holding()) {
      // Hold the next message back until its release, polling for requests meanwhile.
      const double until = answered < recv_req.size() ? std::min(link.nextRelease(), now() + 50e-6)
                                                      : link.nextRelease();
      stats.emulated_wait_seconds += waitUntilSteady(until);
      link.postDue();
    }
  }
  link.waitSent();
  MPI_Waitall(int(reply_recv.size()), reply_recv.data(), MPI_STATUSES_IGNORE);
  stats.seconds = now() - start - stats.answer_seconds;
  return stats;
}

void MpiComm::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();
}

}  // namespace proxyvis
