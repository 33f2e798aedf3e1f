// SPDX-License-Identifier: BSD-3-Clause
/// @file thread_exchange.h
/// @brief Workers as threads of one process, exchanging through memory: the protocol
/// lsrecon-mpi runs over MPI (lsrecon/core/tile_exchange.h).
#pragma once

#include "lsrecon/core/tile_exchange.h"

#include <condition_variable>
#include <mutex>
#include <vector>

namespace lsr {

// Every worker calls all_to_all in the same order.
class ThreadExchange : public TileExchange {
 public:
  struct Meeting {
    explicit Meeting(int n) : workers(n), published(std::size_t(n), nullptr) {}
    void wait() {
      std::unique_lock<std::mutex> lock(mutex);
      const long round = rounds;
      if (++arrived == workers) {
        arrived = 0;
        ++rounds;
        all.notify_all();
      } else {
        all.wait(lock, [&] { return rounds != round; });
      }
    }
    const int workers;
    std::vector<void*> published;
    std::mutex mutex;
    std::condition_variable all;
    int arrived = 0;
    long rounds = 0;
  };
  ThreadExchange(int worker, Meeting& meeting) : worker_(worker), meeting_(meeting) {}
  int worker() const override { return worker_; }
  int workers() const override { return meeting_.workers; }
  void all_to_all(std::vector<std::vector<unsigned char>>& buffers) const override {
    meeting_.published[std::size_t(worker_)] = &buffers;
    meeting_.wait();
    std::vector<std::vector<unsigned char>> in(buffers.size());
    for (int w = 0; w < workers(); ++w) {
      in[std::size_t(w)] = (*static_cast<std::vector<std::vector<unsigned char>>*>(meeting_.published[std::size_t(w)]))[std::size_t(worker_)];
    }
    meeting_.wait();  // nobody changes its buffers before all have copied them
    buffers = std::move(in);
  }

 private:
  int worker_;
  Meeting& meeting_;
};

}  // namespace lsr
