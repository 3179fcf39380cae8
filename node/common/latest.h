#pragma once
// Latest<T>: hands whole immutable snapshots between threads, latest value wins. Readers get
// a shared_ptr to a snapshot that stays valid while they use it; no lock is held while either
// side computes or renders (docs/design.md, "Data flow and threads").
#include <atomic>
#include <cstdint>
#include <memory>
#include <utility>

namespace skyig::services {

template <typename T>
class Latest {
 public:
  void publish(T value) {
    value_.store(std::make_shared<const T>(std::move(value)), std::memory_order_release);
    version_.fetch_add(1, std::memory_order_acq_rel);
  }
  // Builds the snapshot in place: a large value is copied once, not into a temporary first.
  template <typename... Args>
  void emplace(Args&&... args) {
    value_.store(std::make_shared<const T>(std::forward<Args>(args)...), std::memory_order_release);
    version_.fetch_add(1, std::memory_order_acq_rel);
  }
  std::shared_ptr<const T> get() const { return value_.load(std::memory_order_acquire); }
  // Increments on every publish: lets a reader tell whether anything new arrived.
  std::uint64_t version() const { return version_.load(std::memory_order_acquire); }

 private:
  std::atomic<std::shared_ptr<const T>> value_;
  std::atomic<std::uint64_t> version_{0};
};

}  // namespace skyig::services
