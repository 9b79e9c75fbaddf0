// A one-item mailbox between a subscriber callback and a worker: the worker always takes the
// newest item, and an item replaced before the worker took it counts as skipped. This is how
// slam_gmapping keeps up when updates take longer than the scan period: it maps the newest
// scan and says how many it skipped, instead of working through a queue of stale ones (and
// losing the oldest silently when the queue overflows).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <utility>

namespace gmapping_lite {

template <typename T>
class NewestSlot {
 public:
  // Leave `item` for the worker, replacing (and counting as skipped) one not yet taken.
  void put(T item) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (item_) ++skipped_;
      item_ = std::move(item);
      ++offered_;
    }
    ready_.notify_one();
  }

  // Wait for an item; nullopt once close() was called (items left are dropped).
  std::optional<T> take() {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait(lock, [this] { return closed_ || item_.has_value(); });
    if (closed_) return std::nullopt;
    std::optional<T> out = std::move(item_);
    item_.reset();
    return out;
  }

  void close() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
  }

  std::uint64_t offered() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return offered_;
  }
  std::uint64_t skipped() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return skipped_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::optional<T> item_;
  bool closed_ = false;
  std::uint64_t offered_ = 0, skipped_ = 0;
};

}  // namespace gmapping_lite
