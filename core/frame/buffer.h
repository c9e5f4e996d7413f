// An array in the executing side's memory (device memory for CUDA, host memory for the CPU
// policy), owned: allocated through the exec, freed when it goes. Move-only.
#pragma once

#include "core/base/memory.h"

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace sheaf::wavefront {

/// A vector of n values to download into, its pages readied on every core first
/// (prefault_host_pages): a frame's passes are tens of MiB of fresh memory.
template <class T> std::vector<T> host_vector(size_t n) {
    static_assert(std::is_trivially_copyable_v<T>, "raw storage, zeroed before it holds values");
    std::vector<T> v;
    v.reserve(n);
    prefault_host_pages(v.data(), n * sizeof(T));
    v.resize(n);
    return v;
}

template <class T, class Exec> class DeviceBuffer {
  public:
    DeviceBuffer() = default;
    DeviceBuffer(Exec& exec, size_t n) : exec_(&exec), n_(n) {
        if (n) p_ = static_cast<T*>(exec.allocate(n * sizeof(T)));
    }
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;
    DeviceBuffer(DeviceBuffer&& o) noexcept { swap(o); }
    DeviceBuffer& operator=(DeviceBuffer&& o) noexcept {
        DeviceBuffer(std::move(o)).swap(*this);
        return *this;
    }
    ~DeviceBuffer() {
        if (p_) exec_->deallocate(p_, n_ * sizeof(T));
    }

    T* data() const { return p_; }
    size_t size() const { return n_; }
    bool empty() const { return n_ == 0; }

    void upload(const T* src, size_t n, size_t offset = 0) {
        if (n) exec_->copy_to_device(p_ + offset, src, n * sizeof(T));
    }
    std::vector<T> download(size_t n) const {
        std::vector<T> out = host_vector<T>(n);
        if (n) exec_->copy_to_host(out.data(), p_, n * sizeof(T));
        return out;
    }
    std::vector<T> download() const { return download(n_); }
    /// One element, to the host.
    T get(size_t i) const {
        T v;
        exec_->copy_to_host(&v, p_ + i, sizeof(T));
        return v;
    }

  private:
    void swap(DeviceBuffer& o) noexcept {
        std::swap(exec_, o.exec_);
        std::swap(n_, o.n_);
        std::swap(p_, o.p_);
    }
    Exec* exec_ = nullptr;
    size_t n_ = 0;
    T* p_ = nullptr;
};

} // namespace sheaf::wavefront
