#pragma once
// Per-node tables that cost only the pages a run writes.
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace aco {

// A fixed number of T, all bytes zero at the start, in memory the kernel hands out page by page
// (4 kB, never transparent huge pages) where it is first written. A per-node table of the local
// searches, whose ants walk a corridor of a large map, then costs the corridor's pages: an
// 8192x8192 map's 20 bytes per node would be 1.3 GB, of which a corridor writes a few percent.
// Reading an unwritten entry reads zero without allocating. Tables under a megabyte are zeroed on
// the heap.
template <class T>
class ZeroPages {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  ZeroPages() = default;
  explicit ZeroPages(std::size_t size) : size_(size) {
    if (size_ == 0) return;
#ifdef __linux__
    mapped_ = bytes() >= kMapFrom;
    if (mapped_) {
      void* memory = mmap(nullptr, bytes(), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (memory == MAP_FAILED) throw std::bad_alloc();
      madvise(memory, bytes(), MADV_NOHUGEPAGE);
      data_ = static_cast<T*>(memory);
      return;
    }
#endif
    data_ = static_cast<T*>(std::calloc(size_, sizeof(T)));
    if (data_ == nullptr) throw std::bad_alloc();
  }
  ZeroPages(const ZeroPages& other) : ZeroPages(other.size_) {
    if (size_ > 0) std::memcpy(static_cast<void*>(data_), other.data_, bytes());
  }
  ZeroPages(ZeroPages&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)),
        size_(std::exchange(other.size_, 0)),
        mapped_(std::exchange(other.mapped_, false)) {}
  ZeroPages& operator=(ZeroPages other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(mapped_, other.mapped_);
    return *this;
  }
  ~ZeroPages() {
#ifdef __linux__
    if (mapped_) {
      munmap(data_, bytes());
      return;
    }
#endif
    std::free(data_);
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }

 private:
  // Smaller tables (a 512x512 map's) come from the heap: a mapping costs system calls on every
  // run, and their pages are few.
  static constexpr std::size_t kMapFrom = std::size_t{1} << 20;
  std::size_t bytes() const { return size_ * sizeof(T); }
  T* data_ = nullptr;
  std::size_t size_ = 0;
  bool mapped_ = false;
};

}  // namespace aco
