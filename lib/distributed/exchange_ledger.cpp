#include "distributed/exchange_ledger.h"

namespace proxyvis {

void ExchangeLedger::record(const MpiComm::RoundStats& round, double compute_wall) {
  exchange_seconds_ += round.seconds;
  emulated_wait_ += round.emulated_wait_seconds;
  items_sent_ += round.items_sent;
  bytes_sent_ += round.bytes_sent;
  messages_sent_ += round.messages_sent;
  answered_items_ += round.items_answered;
  answer_seconds_ += round.answer_seconds;
  answer_cpu_seconds_ += round.answer_cpu_seconds;
  RoundLoad load;
  load.request = {compute_wall - last_round_wall_ - round.answer_seconds,
                  round.messages_sent - round.answer_messages_sent,
                  round.bytes_sent - round.answer_bytes_sent, round.items_sent};
  load.answer = {round.answer_seconds, round.answer_messages_sent, round.answer_bytes_sent, 0};
  loads_.push_back(load);
  last_round_wall_ = compute_wall;
  batch_.messages += round.messages_sent;
  batch_.bytes += round.bytes_sent;
  batch_.items += round.items_sent;
}

double ExchangeLedger::networkShareSeconds(const NetworkFabric& fabric) const {
  return fabric.sendSeconds(batch_.messages, batch_.bytes, batch_.items) / double(batch_.items);
}

double ExchangeLedger::forwardCostUs(const NetworkFabric& fabric) {
  if (batch_.items == 0) return last_forward_us_;
  const double answer = answered_items_ ? answer_seconds_ / double(answered_items_) : 0.0;
  last_forward_us_ = 1e6 * (networkShareSeconds(fabric) + answer);
  return last_forward_us_;
}

double ExchangeLedger::routeForwardCostUs(const NetworkFabric& fabric, int threads) const {
  if (batch_.items == 0 || answered_items_ == 0) return last_forward_us_;
  const double answer =
      answer_cpu_seconds_ / double(answered_items_) / double(threads > 0 ? threads : 1);
  return 1e6 * (networkShareSeconds(fabric) + answer);
}

}  // namespace proxyvis
